// Rendered error over a whole library: every database page that `library --class all` keeps (or
// the pages matching GLOBs), each model's derived parameters shaded as an engine shades them under
// IBL and area lights (analysis/lut/rendered.h, the lut-accuracy shading points), against
// brute-force spectral integration; median / p90 / p99 / max of the pages' RMS ΔE2000 per model,
// lighting and class. A measurement, not a test.
//   rendered_library [GLOB...]    default '**'
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "analysis/library/library.h"
#include "analysis/lut/rendered.h"
#include "analysis/tables/lut_accuracy.h"
#include "fresnel/registered_models.h"
#include "util/parallel.h"

using namespace fl;

namespace {

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1,
                    static_cast<size_t>(q * static_cast<double>(v.size() - 1) + 0.5))];
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> globs(argv + 1, argv + argc);
  if (globs.empty()) globs = {"**"};
  analysis::Settings settings;
  settings.paths = {FRESNEL_LAB_DEFAULT_DB, FRESNEL_LAB_DEFAULT_MATERIALS};
  const analysis::Context ctx(settings);
  const auto t0 = std::chrono::steady_clock::now();
  analysis::LoadPolicy policy;
  policy.only = std::nullopt;
  const auto set = analysis::load_materials(ctx, globs, policy);
  const std::vector<std::string> names{"schlick", "f82", "basis3", "basis4", "basis5"};
  analysis::StudyOptions options;
  options.fit = false;
  options.method_errors = false;
  for (const auto& n : names) options.models.push_back(fresnel::model_from_name(n).model);
  const auto studies = analysis::study_materials(ctx, set.materials, options);
  const auto points = analysis::lut_accuracy_points();
  // rms[page][model][lighting]
  std::vector<std::vector<std::array<double, 2>>> rms(studies.size());
  parallel_for(studies.size(), [&](size_t i) {
    const auto truth = analysis::lobe_truth(ctx, *studies[i].material, points);
    for (const auto& r : studies[i].models) {
      std::array<double, 2> e{};
      int k = 0;
      for (auto l : {analysis::Lighting::Ibl, analysis::Lighting::Area})
        e[k++] = analysis::error_stats(
                     analysis::rendered_de00(ctx, truth, r.model, r.derived, l, points))
                     .rms;
      rms[i].push_back(e);
    }
  });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  fmt::print("{} pages ({} skipped), {:.1f} s\n", studies.size(), set.skipped.size(), seconds);
  fmt::print("class,model,lighting,pages,median,p90,p99,max\n");
  for (const char* cls : {"all", "metal", "dielectric"})
    for (size_t m = 0; m < names.size(); ++m)
      for (int l = 0; l < 2; ++l) {
        std::vector<double> v;
        for (size_t i = 0; i < studies.size(); ++i) {
          const bool metal =
              studies[i].material->material.material_class == spectral::MaterialClass::Metal;
          if (std::string(cls) == "all" || (std::string(cls) == "metal") == metal)
            v.push_back(rms[i][m][l]);
        }
        fmt::print("{},{},{},{},{:.3f},{:.3f},{:.3f},{:.3f}\n", cls, names[m], l ? "area" : "ibl",
                   v.size(), quantile(v, 0.5), quantile(v, 0.9), quantile(v, 0.99),
                   quantile(v, 1.0));
      }
  // Pages where a basis model renders worse than F82 derived (index 1 in `names`).
  for (size_t m = 2; m < names.size(); ++m)
    for (int l = 0; l < 2; ++l) {
      int worse = 0;
      std::string worst;
      double gap = 0;
      for (size_t i = 0; i < studies.size(); ++i) {
        const double d = rms[i][m][l] - rms[i][1][l];
        if (d <= 0) continue;
        ++worse;
        if (d > gap) gap = d, worst = studies[i].material->material.name;
      }
      fmt::print("{} {}: worse than f82 on {} pages{}\n", names[m], l ? "area" : "ibl", worse,
                 worse ? fmt::format(" (largest gap {:.3f}: {})", gap, worst) : "");
    }
  return 0;
}
