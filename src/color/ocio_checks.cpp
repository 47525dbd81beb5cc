#include "color/ocio_checks.h"

#include <fmt/format.h>

#include <algorithm>

#include "spectral/text_file.h"
#include "util/errors.h"

namespace OCIO = OCIO_NAMESPACE;

namespace fl::color {
namespace {

// Every file a transform reads, checked as any input is (a LUT that is a FIFO would block OCIO).
void check_transform_files(const OCIO::Config& config, const OCIO::ConstTransformRcPtr& t,
                           const std::string& path, const std::string& space) {
  if (!t) return;
  if (const auto group = OCIO::DynamicPtrCast<const OCIO::GroupTransform>(t)) {
    for (int i = 0; i < group->getNumTransforms(); ++i)
      check_transform_files(config, group->getTransform(i), path, space);
    return;
  }
  const auto file = OCIO::DynamicPtrCast<const OCIO::FileTransform>(t);
  if (!file) return;
  std::string resolved;
  try {
    resolved = config.getCurrentContext()->resolveFileLocation(file->getSrc());
  } catch (const OCIO::Exception& e) {
    throw InputError(
        path, config_line(path, file->getSrc()),
        fmt::format("colour space '{}' reads a file OpenColorIO cannot find: {}", space, e.what()));
  }
  spectral::check_input_file(resolved);
}

}  // namespace

int config_line(const std::string& path, const std::string& needle) {
  std::string text;
  try {
    text = spectral::read_input_bytes(path);
  } catch (const InputError&) {
    return 0;
  }
  const size_t at = text.find(needle);
  if (needle.empty() || at == std::string::npos) return 0;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

void validate_config(const OCIO::Config& config, const std::string& path) {
  for (int i = 0; i < config.getNumRoles(); ++i) {
    const std::string role = config.getRoleName(i), space = config.getRoleColorSpace(i);
    if (!config.getColorSpace(space.c_str()))
      throw InputError(path, config_line(path, role + ":"),
                       fmt::format("role '{}' names colour space '{}', which the config does not "
                                   "define",
                                   role, space));
  }
  try {
    config.validate();
  } catch (const OCIO::Exception& e) {
    throw InputError(path, 0, std::string("invalid OCIO config: ") + e.what());
  }
}

void require_colour_space(const OCIO::Config& config, const std::string& path,
                          const std::string& name, const std::string& use) {
  const auto cs = config.getColorSpace(name.c_str());
  if (!cs) throw InputError(path, 0, fmt::format("no colour space '{}' in the config", name));
  if (cs->isData())
    throw InputError(
        path, config_line(path, "name: " + std::string(cs->getName())),
        fmt::format("colour space '{}' is data (isdata: true): OpenColorIO passes data through "
                    "unconverted, so it cannot be {}",
                    name, use));
  for (const auto dir : {OCIO::COLORSPACE_DIR_TO_REFERENCE, OCIO::COLORSPACE_DIR_FROM_REFERENCE})
    check_transform_files(config, cs->getTransform(dir), path, name);
}

}  // namespace fl::color
