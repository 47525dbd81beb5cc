#pragma once
// Reading a YAML input file with the project's error conventions.
#include <yaml-cpp/yaml.h>

#include <string>

namespace fl::spectral {

// The file's YAML document (read_text_file's checks, then yaml-cpp). A syntax error becomes an
// InputError naming the file and line.
YAML::Node read_yaml_file(const std::string& path);

}  // namespace fl::spectral
