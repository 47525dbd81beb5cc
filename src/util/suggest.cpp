#include "util/suggest.h"

#include <algorithm>

namespace fl {
namespace {

char fold(char c) {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

// The spelling names are compared in: ASCII lower case, '-' and ' ' as '_'.
std::string folded_name(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = c == '-' || c == ' ' ? '_' : fold(c);
  return out;
}

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Wagner–Fischer with the adjacent-transposition case (Damerau 1964), three rows of the table.
  const std::size_t n = b.size();
  std::vector<std::size_t> before(n + 1), previous(n + 1), current(n + 1);
  for (std::size_t j = 0; j <= n; ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= n; ++j) {
      const bool same = fold(a[i - 1]) == fold(b[j - 1]);
      current[j] =
          std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
      if (i > 1 && j > 1 && fold(a[i - 1]) == fold(b[j - 2]) && fold(a[i - 2]) == fold(b[j - 1]))
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[n];
}

std::optional<std::string> closest_match(std::string_view name,
                                         const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  std::size_t best_distance = 0;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(name, c);
    const std::size_t allowed = std::max<std::size_t>(1, 2 * std::max(name.size(), c.size()) / 5);
    if (d > allowed || (best && d >= best_distance)) continue;
    best = c;
    best_distance = d;
  }
  return best;
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates) {
  const auto match = closest_match(name, candidates);
  return match ? " (did you mean '" + *match + "'?)" : std::string();
}

std::optional<std::string> match_name(std::string_view typed,
                                      const std::vector<NameChoice>& choices) {
  const std::string want = folded_name(typed);
  for (const auto& c : choices) {
    if (folded_name(c.name) == want) return c.name;
    for (const auto& a : c.aliases)
      if (folded_name(a) == want) return c.name;
  }
  return std::nullopt;
}

std::string unknown_name_message(std::string_view what, std::string_view typed,
                                 const std::vector<NameChoice>& choices) {
  std::vector<std::string> spellings, names;
  std::vector<const std::string*> stands_for;
  for (const auto& c : choices) {
    names.push_back(c.name);
    spellings.push_back(folded_name(c.name));
    stands_for.push_back(&c.name);
    for (const auto& a : c.aliases) {
      spellings.push_back(folded_name(a));
      stands_for.push_back(&c.name);
    }
  }
  std::string message = "unknown " + std::string(what) + " '" + std::string(typed) + "'";
  if (const auto close = closest_match(folded_name(typed), spellings)) {
    const auto at = std::find(spellings.begin(), spellings.end(), *close) - spellings.begin();
    message += ": did you mean '" + *stands_for[static_cast<std::size_t>(at)] + "'?";
  }
  message += " (expected ";
  for (std::size_t i = 0; i < names.size(); ++i)
    message += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return message + ")";
}

}  // namespace fl
