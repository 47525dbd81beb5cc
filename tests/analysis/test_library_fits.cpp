// The library's curve fits, stopped at kLibraryFitTolerance, against the same fits run further.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/library/library.h"
#include "analysis/pipeline/materials.h"
#include "analysis/study/study.h"
#include "fresnel/registry.h"

namespace fl::analysis {
namespace {

// Metal pages whose fits run longest or end in flat valleys (RGB η and κ, generalized Schlick),
// beside the usual ones, and the liquid methane whose Cook–Torrance fit descends slowest.
const std::vector<std::string> kPages{"organic/CH4 - methane/nk/Martonchik-liquid-90K",
                                      "main/Au/nk/Johnson",
                                      "main/Ag/nk/Johnson",
                                      "main/Cu/nk/Johnson",
                                      "main/Al/nk/Rakic",
                                      "main/Zn/nk/Querry",
                                      "main/Cs/nk/Smith",
                                      "main/Cr/nk/Johnson",
                                      "main/Ti/nk/Johnson",
                                      "main/W/nk/Weaver",
                                      "main/PtSe2/nk/Tharrault-1L",
                                      "main/MoOCl2/nk/Ermolaev-alpha"};

TEST(LibraryFits, StopWhereThePrintedErrorsCanNoLongerMove) {
  const Context ctx{[] {
    Settings s;
    s.paths = {FL_DEFAULT_DB, FL_MATERIALS};
    return s;
  }()};
  LoadPolicy policy;
  policy.only = std::nullopt;
  policy.min_coverage = 0;
  const auto set = load_materials(ctx, kPages, policy);
  ASSERT_EQ(set.materials.size(), kPages.size());
  StudyOptions library, further;
  library.fit_tolerance = kLibraryFitTolerance;
  further.fit_tolerance = 1e-13;
  const auto a = study_materials(ctx, set.materials, library);
  const auto b = study_materials(ctx, set.materials, further);
  double largest = 0;
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t k = 0; k < a[i].models.size(); ++k) {
      const double d = a[i].models[k].fitted_error.rms - b[i].models[k].fitted_error.rms;
      EXPECT_LE(std::abs(d), kLibraryFitRmsBound)
          << kPages[i] << " " << fresnel::model_spec(a[i].models[k].model).name;
      largest = std::max(largest, std::abs(d));
    }
  std::printf("largest RMS ΔE2000 difference: %.2e (bound %.0e)\n", largest, kLibraryFitRmsBound);
}

}  // namespace
}  // namespace fl::analysis
