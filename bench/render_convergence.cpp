// How many samples a sphere render needs for its ΔE2000 heat maps to stop changing: renders
// materials under HDR environments at increasing sample counts and compares each heat map with one
// rendered at a reference count, pixel by pixel (max and 99.9th percentile of |ΔE − ΔE_ref|),
// and times each pass. Prints a Markdown table.
//   render_convergence --env DIR [--size N] [--roughness R] [--reference N] [--counts a,b]
//   [--materials a,b]
//                      [--envs a,b]
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "analysis/render/environment_file.h"
#include "analysis/render/render.h"
#include "jobs/pictures.h"

using namespace fl;

namespace {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= s.size()) {
    const size_t end = std::min(s.find(',', start), s.size());
    out.push_back(s.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

struct Options {
  std::string env_dir, materials = "gold,chromium,glass_bk7", envs = "studio,sunset";
  int size = 256, reference = 2048;
  double roughness = 0.25;
  std::vector<int> counts{16, 32, 64, 128, 256, 512, 1024};
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--env")
      o.env_dir = v;
    else if (k == "--size")
      o.size = std::stoi(v);
    else if (k == "--roughness")
      o.roughness = std::stod(v);
    else if (k == "--reference")
      o.reference = std::stoi(v);
    else if (k == "--materials")
      o.materials = v;
    else if (k == "--envs")
      o.envs = v;
    else if (k == "--counts") {
      o.counts.clear();
      for (const auto& c : split(v)) o.counts.push_back(std::stoi(c));
    }
  }
  return o;
}

// max and 99.9th percentile of |a − b| over pixels where both are finite.
std::pair<double, double> difference(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> d;
  for (size_t k = 0; k < a.size(); ++k)
    if (std::isfinite(a[k]) && std::isfinite(b[k])) d.push_back(std::abs(a[k] - b[k]));
  std::sort(d.begin(), d.end());
  if (d.empty()) return {0, 0};
  return {d.back(), d[static_cast<size_t>(0.999 * (d.size() - 1))]};
}

analysis::MaterialRender timed_render(const analysis::Context& ctx,
                                      const analysis::LoadedMaterial& m,
                                      const analysis::SceneLight& light, const Options& o,
                                      int samples, double& secs) {
  analysis::RenderSettings rs;
  rs.size_px = o.size;
  rs.roughness = o.roughness;
  rs.samples = samples;
  const auto t0 = std::chrono::steady_clock::now();
  auto r = analysis::render_material(ctx, m, light, jobs::parse_models("schlick,f82,gulbrandsen"),
                                     "derived", rs);
  secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  analysis::Settings settings;
  settings.paths = {FRESNEL_LAB_DEFAULT_DB, FRESNEL_LAB_DEFAULT_MATERIALS};
  const analysis::Context ctx(settings);
  fmt::print(
      "Heat-map convergence: {}² px, roughness {:g}, reference {} samples per strategy; |ΔE2000 − "
      "reference| "
      "over the models schlick, f82, gulbrandsen (max over the three)\n\n",
      o.size, o.roughness, o.reference);
  fmt::print(
      "| material | environment | samples | max | p99.9 | seconds (4 images, one pass) "
      "|\n|---|---|---|---|---|---|\n");
  for (const auto& env_name : split(o.envs)) {
    const auto env = analysis::load_environment(ctx, o.env_dir + "/" + env_name + ".exr", "", 0, 0);
    const analysis::SceneLight light = env.map;
    for (const auto& name : split(o.materials)) {
      const auto m = analysis::load_material(ctx, spectral::resolve_material(name, settings.paths));
      double secs = 0;
      const auto ref = timed_render(ctx, m, light, o, o.reference, secs);
      for (int n : o.counts) {
        const auto r = timed_render(ctx, m, light, o, n, secs);
        double worst = 0, worst_p = 0;
        for (size_t i = 0; i < r.models.size(); ++i) {
          const auto [mx, p] = difference(r.models[i].de2000, ref.models[i].de2000);
          worst = std::max(worst, mx), worst_p = std::max(worst_p, p);
        }
        fmt::print("| {} | {} | {} | {:.3f} | {:.3f} | {:.2f} |\n", m.material.name, env_name, n,
                   worst, worst_p, secs);
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
