#include "spectral/yaml_file.h"

#include <yaml.h>

#include <algorithm>
#include <map>
#include <new>

#include "spectral/text_file.h"
#include "util/errors.h"

namespace fl::spectral {

const YamlNode& YamlNode::operator[](std::string_view key) const {
  static const YamlNode undefined;
  for (const auto& [k, v] : fields_)
    if (k.kind_ == Kind::Scalar && k.text_ == key) return v;
  return undefined;
}

std::string YamlNode::as_string() const {
  if (kind_ == Kind::Null) return "null";
  if (kind_ != Kind::Scalar) throw YamlError(line_, "bad conversion");
  return text_;
}

// Builds the tree from libyaml's events, one node per call of node().
class YamlBuilder {
 public:
  explicit YamlBuilder(std::string_view text) : text_(text) {
    if (!yaml_parser_initialize(&parser_)) throw std::bad_alloc();
    yaml_parser_set_input_string(&parser_, reinterpret_cast<const unsigned char*>(text.data()),
                                 text.size());
  }
  ~YamlBuilder() {
    if (have_event_) yaml_event_delete(&event_);
    yaml_parser_delete(&parser_);
  }
  YamlBuilder(const YamlBuilder&) = delete;
  YamlBuilder& operator=(const YamlBuilder&) = delete;

  YamlNode document() {
    YamlNode root;
    root.kind_ = YamlNode::Kind::Null;
    root.line_ = 0;
    for (next(); event_.type != YAML_STREAM_END_EVENT; next())
      if (event_.type != YAML_STREAM_START_EVENT && event_.type != YAML_DOCUMENT_START_EVENT) {
        node(root);
        break;
      }
    if (event_.type == YAML_STREAM_END_EVENT) return root;
    // A second document would be silently dropped: refused instead.
    for (next(); event_.type != YAML_STREAM_END_EVENT; next())
      if (event_.type == YAML_DOCUMENT_START_EVENT)
        throw YamlError(static_cast<int>(event_.start_mark.line),
                        "a second YAML document ('---'): a file holds one document");
    return root;
  }

 private:
  void next() {
    if (have_event_) yaml_event_delete(&event_);
    have_event_ = yaml_parser_parse(&parser_, &event_) != 0;
    if (!have_event_) fail();
  }
  [[noreturn]] void fail() const {
    if (parser_.error == YAML_MEMORY_ERROR) throw std::bad_alloc();
    std::string what = parser_.problem ? parser_.problem : "syntax error";
    if (parser_.context) what = std::string(parser_.context) + ", " + what;
    // A tab where YAML expects indentation or a token: libyaml's "found character that cannot
    // start any token" names neither the character nor the rule.
    const size_t at = parser_.problem_mark.index;
    if (parser_.error == YAML_SCANNER_ERROR && at < text_.size() && text_[at] == '\t')
      what = "a tab at column " + std::to_string(parser_.problem_mark.column + 1) +
             ": YAML indents with spaces, not tabs";
    // The reader (bad UTF-8, control bytes) gives a byte offset, not a mark.
    int line = static_cast<int>(parser_.problem_mark.line);
    if (parser_.error == YAML_READER_ERROR) {
      const size_t end = std::min(parser_.problem_offset, text_.size());
      line = static_cast<int>(
          std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
    }
    throw YamlError(line, what);
  }
  void count(size_t nodes, int line) {
    nodes_ += nodes;
    if (nodes_ > kMaxYamlNodes)
      throw YamlError(line, "more than " + std::to_string(kMaxYamlNodes) + " nodes");
  }

  // The node whose first event is the current one, `depth` collections deep; its anchor, if any,
  // is remembered with the number of nodes it holds.
  void node(YamlNode& out, int depth = 0) {
    out.line_ = static_cast<int>(event_.start_mark.line);
    if (event_.type == YAML_ALIAS_EVENT) {
      const auto it = anchors_.find(reinterpret_cast<const char*>(event_.data.alias.anchor));
      if (it == anchors_.end()) throw YamlError(out.line_, "unknown anchor");
      count(it->second.second, out.line_);
      const int line = out.line_;
      out = it->second.first;
      out.line_ = line;
      return;
    }
    if (depth > kMaxYamlDepth)
      throw YamlError(out.line_, "nested deeper than " + std::to_string(kMaxYamlDepth));
    const size_t first = nodes_;
    count(1, out.line_);
    std::string anchor;
    const auto take_anchor = [&](const yaml_char_t* a) {
      if (a) anchor = reinterpret_cast<const char*>(a);
    };
    if (event_.type == YAML_SCALAR_EVENT) {
      const auto& s = event_.data.scalar;
      take_anchor(s.anchor);
      out.text_.assign(reinterpret_cast<const char*>(s.value), s.length);
      // YAML's core schema: an untagged plain scalar spelled as null is a null.
      const bool null = s.tag == nullptr && s.style == YAML_PLAIN_SCALAR_STYLE &&
                        (out.text_.empty() || out.text_ == "~" || out.text_ == "null" ||
                         out.text_ == "Null" || out.text_ == "NULL");
      out.kind_ = null ? YamlNode::Kind::Null : YamlNode::Kind::Scalar;
      if (null) out.text_.clear();
    } else if (event_.type == YAML_SEQUENCE_START_EVENT) {
      take_anchor(event_.data.sequence_start.anchor);
      out.kind_ = YamlNode::Kind::Sequence;
      for (next(); event_.type != YAML_SEQUENCE_END_EVENT; next())
        node(out.items_.emplace_back(), depth + 1);
    } else if (event_.type == YAML_MAPPING_START_EVENT) {
      take_anchor(event_.data.mapping_start.anchor);
      out.kind_ = YamlNode::Kind::Map;
      std::map<std::string, int> keys;  // a scalar key's first line
      for (next(); event_.type != YAML_MAPPING_END_EVENT; next()) {
        auto& field = out.fields_.emplace_back();
        node(field.first, depth + 1);
        if (field.first.is_scalar()) {
          const auto [first, added] = keys.emplace(field.first.text_, field.first.line_);
          if (!added)
            throw YamlError(field.first.line_, "repeated key '" + field.first.text_ +
                                                   "' (first at line " +
                                                   std::to_string(first->second + 1) + ")");
        }
        next();
        node(field.second, depth + 1);
      }
    } else {
      throw YamlError(out.line_, "unexpected event");
    }
    if (!anchor.empty()) anchors_[anchor] = {out, nodes_ - first};
  }

  std::string_view text_;
  yaml_parser_t parser_{};
  yaml_event_t event_{};
  bool have_event_ = false;
  size_t nodes_ = 0;
  std::map<std::string, std::pair<YamlNode, size_t>>
      anchors_;  // an anchor's node and its node count
};

YamlNode parse_yaml(std::string_view text) {
  return YamlBuilder(text).document();
}

YamlNode read_yaml_file(const std::string& path) {
  const std::string text = read_text_file(path);
  try {
    return parse_yaml(text);
  } catch (const YamlError& e) {
    throw InputError(path, e.line + 1, std::string("invalid YAML: ") + e.what());
  }
}

}  // namespace fl::spectral
