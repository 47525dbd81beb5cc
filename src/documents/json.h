#pragma once
// JSON documents through nlohmann/json (included by documents/ sources only): built as ordered_json
// (members keep their insertion order) and written in one fixed layout, so the same values give
// the same bytes:
//   - the top-level object has one member per line (two-space indent), and so has each of its
//     arrays of objects (one object per line); everything deeper is on one line, as
//     {"key": value, "key": value} and [value, value];
//   - a float member is written with a fixed number of decimals, `decimals(key)` (elements of an
//     array take the array's key), "-0.000" as "0.000" (format_number), non-finite as null;
//   - strings are escaped by nlohmann/json (UTF-8 kept; invalid UTF-8 replaced by U+FFFD).
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace fl::documents {

using Json = nlohmann::ordered_json;

std::string write_json(const Json& document,
                       const std::function<int(const std::string& key)>& decimals);

}  // namespace fl::documents
