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

}  // namespace fl
