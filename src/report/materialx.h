#pragma once
// The presets as a MaterialX document.
#include <string>
#include <vector>

#include "analysis/study/study.h"

namespace fl::report {

// A MaterialX document with one generalized_schlick_bsdf (color0, color82) per material.
std::string presets_materialx(const analysis::Context& ctx, const std::vector<analysis::MaterialStudy>& studies);

}  // namespace fl::report
