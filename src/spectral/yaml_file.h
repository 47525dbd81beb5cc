#pragma once
// YAML input read with libyaml's event parser into a small document tree, with the project's
// error conventions. libyaml stays inside yaml_file.cpp.
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fl::spectral {

// A conversion a document does not allow, e.g. a list read as text; line is 0-based.
struct YamlError : std::runtime_error {
  YamlError(int line, const std::string& what) : std::runtime_error(what), line(line) {}
  int line;
};

// One node of a YAML document: a scalar (kept as its text), a sequence, a map, a null (an untagged
// empty, ~ or null plain scalar) or, for a key a map lacks, undefined. Aliases are resolved to a
// copy of their anchor's node (at the alias's line).
class YamlNode {
 public:
  enum class Kind { Undefined, Null, Scalar, Sequence, Map };

  Kind kind() const { return kind_; }
  explicit operator bool() const { return kind_ != Kind::Undefined; }  // present (null counts)
  bool is_null() const { return kind_ == Kind::Null; }
  bool is_scalar() const { return kind_ == Kind::Scalar; }
  bool is_sequence() const { return kind_ == Kind::Sequence; }
  bool is_map() const { return kind_ == Kind::Map; }
  int line() const { return line_; }  // 0-based, where the node starts

  // The value under `key`; undefined when this is not a map or has no such key.
  const YamlNode& operator[](std::string_view key) const;
  // A scalar's text ("" for anything else).
  const std::string& scalar() const { return text_; }
  // A scalar's text, "null" for a null; YamlError("bad conversion") for a list or map.
  std::string as_string() const;
  const std::vector<YamlNode>& items() const { return items_; }  // a sequence's
  const std::vector<std::pair<YamlNode, YamlNode>>& fields() const {
    return fields_;
  }  // a map's, in order
  size_t size() const { return kind_ == Kind::Map ? fields_.size() : items_.size(); }

 private:
  friend class YamlBuilder;
  Kind kind_ = Kind::Undefined;
  int line_ = -1;
  std::string text_;
  std::vector<YamlNode> items_;
  std::vector<std::pair<YamlNode, YamlNode>> fields_;
};

// The one document of `text` (a null node when there is none; a second document is a YamlError). A
// syntax error is a YamlError at the line libyaml found it, its message libyaml's ("did not find
// expected ',' or '}'"); so is text that is not UTF-8, a map that repeats a key (YAML requires
// unique keys; libyaml does not check), collections nested deeper than kMaxYamlDepth, and a
// document of more than kMaxYamlNodes nodes once its aliases are copied (a few aliases of aliases
// can stand for billions).
inline constexpr int kMaxYamlDepth = 1000;
inline constexpr size_t kMaxYamlNodes = 1'000'000;
YamlNode parse_yaml(std::string_view text);

// The file's YAML document (read_text_file's checks, then parse_yaml). A syntax error becomes an
// InputError naming the file and line: "invalid YAML: ...".
YamlNode read_yaml_file(const std::string& path);

}  // namespace fl::spectral
