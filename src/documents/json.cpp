#include "documents/json.h"

#include <cmath>

#include "documents/table_formats.h"

namespace fl::documents {
namespace {

using Decimals = std::function<int(const std::string& key)>;

std::string string_text(const std::string& s) {
  return Json(s).dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string scalar_text(const Json& v, const std::string& key, const Decimals& decimals) {
  if (v.is_number_float()) {
    const double x = v.get<double>();
    return std::isfinite(x) ? format_number(x, decimals(key)) : "null";
  }
  return v.is_string() ? string_text(v.get<std::string>()) : v.dump();
}

// A value on one line; `key` is the member name it belongs to.
std::string inline_text(const Json& v, const std::string& key, const Decimals& decimals) {
  if (v.is_object()) {
    std::string out = "{";
    for (auto it = v.begin(); it != v.end(); ++it)
      out += (it == v.begin() ? "" : ", ") + string_text(it.key()) + ": " +
             inline_text(it.value(), it.key(), decimals);
    return out + "}";
  }
  if (v.is_array()) {
    std::string out = "[";
    for (size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + inline_text(v[i], key, decimals);
    return out + "]";
  }
  return scalar_text(v, key, decimals);
}

bool is_array_of_objects(const Json& v) {
  if (!v.is_array() || v.empty()) return false;
  for (const auto& e : v)
    if (!e.is_object()) return false;
  return true;
}

}  // namespace

std::string write_json(const Json& document, const Decimals& decimals) {
  if (!document.is_object() || document.empty()) return inline_text(document, "", decimals) + "\n";
  std::string out = "{";
  for (auto it = document.begin(); it != document.end(); ++it) {
    out += (it == document.begin() ? "\n  " : ",\n  ") + string_text(it.key()) + ": ";
    const Json& v = it.value();
    if (!is_array_of_objects(v)) {
      out += inline_text(v, it.key(), decimals);
      continue;
    }
    out += "[";
    for (size_t i = 0; i < v.size(); ++i)
      out += (i ? ",\n    " : "\n    ") + inline_text(v[i], it.key(), decimals);
    out += "\n  ]";
  }
  return out + "\n}\n";
}

}  // namespace fl::documents
