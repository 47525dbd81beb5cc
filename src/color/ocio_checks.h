#pragma once
// Checks of an OpenColorIO config before Fresnel Lab builds anything from it. Internal to the
// color module (it includes OCIO's header); errors are InputErrors naming the config file and,
// where the defect is found in its text, the line.
#include <OpenColorIO/OpenColorIO.h>

#include <string>

namespace fl::color {

// The config as loaded from `path`: every role names a colour space the config defines, then
// OCIO's own validation (Config::validate). Without this, a role naming a missing space (a typo, a
// truncated file) gives a null colour space.
void validate_config(const OCIO_NAMESPACE::Config& config, const std::string& path);

// A space Fresnel Lab converts colours to or from: defined, not data (isdata: true marks values
// that are not colours: OCIO converts them unchanged), and every file its transforms read (LUTs)
// a regular file of bounded size (spectral/text_file.h, check_input_file). `use` says what the
// space is for ("the working space"). Linearity is checked when the matrix is built.
void require_colour_space(const OCIO_NAMESPACE::Config& config, const std::string& path,
                          const std::string& name, const std::string& use);

// The 1-based line of `path` where `needle` first appears (0 when it does not, or the file cannot
// be read): where a defect of the config's text is.
int config_line(const std::string& path, const std::string& needle);

}  // namespace fl::color
