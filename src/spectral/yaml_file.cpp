#include "spectral/yaml_file.h"

#include <yaml.h>

#include <map>

#include "spectral/errors.h"
#include "spectral/text_file.h"

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
  explicit YamlBuilder(std::string_view text) {
    yaml_parser_initialize(&parser_);
    yaml_parser_set_input_string(&parser_, reinterpret_cast<const unsigned char*>(text.data()), text.size());
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
    return root;
  }

 private:
  void next() {
    if (have_event_) yaml_event_delete(&event_);
    have_event_ = yaml_parser_parse(&parser_, &event_) != 0;
    if (!have_event_) {
      std::string what = parser_.problem ? parser_.problem : "syntax error";
      if (parser_.context) what = std::string(parser_.context) + ", " + what;
      throw YamlError(static_cast<int>(parser_.problem_mark.line), what);
    }
  }

  // The node whose first event is the current one; its anchor, if any, is remembered.
  void node(YamlNode& out) {
    out.line_ = static_cast<int>(event_.start_mark.line);
    std::string anchor;
    switch (event_.type) {
      case YAML_ALIAS_EVENT: {
        const auto it = anchors_.find(reinterpret_cast<const char*>(event_.data.alias.anchor));
        if (it == anchors_.end()) throw YamlError(out.line_, "unknown anchor");
        const int line = out.line_;
        out = it->second;
        out.line_ = line;
        return;
      }
      case YAML_SCALAR_EVENT: {
        const auto& s = event_.data.scalar;
        if (s.anchor) anchor = reinterpret_cast<const char*>(s.anchor);
        out.text_.assign(reinterpret_cast<const char*>(s.value), s.length);
        const bool plain = s.style == YAML_PLAIN_SCALAR_STYLE;
        const bool null = plain && (out.text_.empty() || out.text_ == "~" || out.text_ == "null" ||
                                    out.text_ == "Null" || out.text_ == "NULL");
        out.kind_ = null ? YamlNode::Kind::Null : YamlNode::Kind::Scalar;
        if (null) out.text_.clear();
        break;
      }
      case YAML_SEQUENCE_START_EVENT:
        if (event_.data.sequence_start.anchor) anchor = reinterpret_cast<const char*>(event_.data.sequence_start.anchor);
        out.kind_ = YamlNode::Kind::Sequence;
        for (next(); event_.type != YAML_SEQUENCE_END_EVENT; next()) node(out.items_.emplace_back());
        break;
      case YAML_MAPPING_START_EVENT:
        if (event_.data.mapping_start.anchor) anchor = reinterpret_cast<const char*>(event_.data.mapping_start.anchor);
        out.kind_ = YamlNode::Kind::Map;
        for (next(); event_.type != YAML_MAPPING_END_EVENT; next()) {
          auto& field = out.fields_.emplace_back();
          node(field.first);
          next();
          node(field.second);
        }
        break;
      default:
        throw YamlError(out.line_, "unexpected event");
    }
    if (!anchor.empty()) anchors_[anchor] = out;
  }

  yaml_parser_t parser_{};
  yaml_event_t event_{};
  bool have_event_ = false;
  std::map<std::string, YamlNode> anchors_;
};

YamlNode parse_yaml(std::string_view text) { return YamlBuilder(text).document(); }

YamlNode read_yaml_file(const std::string& path) {
  const std::string text = read_text_file(path);
  try {
    return parse_yaml(text);
  } catch (const YamlError& e) {
    throw InputError(path, e.line + 1, std::string("invalid YAML: ") + e.what());
  }
}

}  // namespace fl::spectral
