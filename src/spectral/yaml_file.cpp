#include "spectral/yaml_file.h"

#include "spectral/errors.h"
#include "spectral/text_file.h"

namespace fl::spectral {

YAML::Node read_yaml_file(const std::string& path) {
  const std::string text = read_text_file(path);
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(path, e.mark.line + 1, "invalid YAML: " + e.msg);
  }
}

}  // namespace fl::spectral
