#pragma once
// "Did you mean ...?" for a name that is not one of the known ones (keys of an input file, names
// on the command line): the nearest known name by edit distance, ignoring ASCII case.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl {

// The optimal-string-alignment distance (Damerau–Levenshtein restricted to edits that do not
// overlap): the fewest insertions, deletions, substitutions and swaps of two adjacent characters
// turning `a` into `b`, comparing ASCII letters case-insensitively. ("teh" → "the" is 1; "ca" →
// "abc" is 3, where unrestricted Damerau–Levenshtein gives 2.)
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate nearest to `name` by edit_distance, if it is close: at most 2/5 of the longer of
// the two (at least 1) edits away, so that "refrence" finds "reference" and "lights" finds
// "lighting" while "abc" does not find "ibl". Ties go to the earlier candidate; a candidate equal
// to `name` (ignoring case) is found at distance 0.
std::optional<std::string> closest_match(std::string_view name,
                                         const std::vector<std::string>& candidates);

// " (did you mean 'X'?)" with closest_match's X, or "" when nothing is close: for appending to an
// error message.
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates);

// A name a user may type for one thing: its canonical spelling and the other spellings accepted
// for it ("aluminium" for "aluminum", "lin_srgb" for "lin_rec709").
struct NameChoice {
  std::string name;
  std::vector<std::string> aliases;
};

// The canonical name `typed` stands for: equal to a choice's name or one of its aliases, ignoring
// ASCII case and treating '-', '_' and ' ' as one character; nullopt when none is.
std::optional<std::string> match_name(std::string_view typed,
                                      const std::vector<NameChoice>& choices);

// "unknown WHAT 'TYPED' (expected a, b or c)", with ": did you mean 'X'?" after the name when a
// name or alias is close (an alias that is close suggests the name it stands for).
std::string unknown_name_message(std::string_view what, std::string_view typed,
                                 const std::vector<NameChoice>& choices);

}  // namespace fl
