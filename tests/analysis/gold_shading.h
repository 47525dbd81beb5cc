#pragma once
// Gold at lut-accuracy's shading points with its brute-force lobe truth: the fixture of the tests
// of rendered errors.
#include <vector>

#include "analysis/lut/lut_accuracy.h"
#include "analysis/pipeline/materials.h"

namespace fl::analysis::test {

struct GoldShading {
  Context ctx{[] {
    Settings s;
    s.paths = {FL_DEFAULT_DB, FL_MATERIALS};
    return s;
  }()};
  MaterialSet set = load_materials(ctx, {"gold"}, {});
  MaterialStudy study;
  std::vector<ShadingPoint> points = lut_accuracy_points();
  std::vector<color::Rgb> truth = lobe_truth(ctx, set.materials.front(), points);

  explicit GoldShading(const StudyOptions& options = {})
      : study(study_materials(ctx, set.materials, options).front()) {}
};

}  // namespace fl::analysis::test
