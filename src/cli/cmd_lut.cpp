// `lut dfg | ltc-moments | ltc`: pre-integrated GGX lookup tables as EXR textures, CSV and C++
// headers.
#include <fmt/format.h>

#include <chrono>
#include <memory>

#include "cli/app.h"
#include "jobs/lut_files.h"

namespace fl::cli {
namespace {

// Progress on stderr in 10 % steps (nothing with -q).
analysis::LutProgress progress_printer(const GlobalOptions& g, const std::string& what) {
  if (g.quiet) return {};
  auto last = std::make_shared<int>(-1);
  const auto t0 = std::chrono::steady_clock::now();
  return [&g, what, last, t0](int done, int total) {
    const int pct = total > 0 ? 100 * done / total : 100;
    if (pct / 10 == *last / 10 && pct != 100) return;
    if (pct == *last) return;
    *last = pct;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    progress(g, fmt::format("{}: {:3d}% ({:.1f} s)", what, pct, s));
  };
}

using LutRun = report::Output (*)(const report::LutRequest&, const analysis::LutProgress&);

CLI::App* add_lut_subcommand(CLI::App& lut, GlobalOptions& g, Runner& selected, const char* name,
                             const char* help, const char* out_help, LutRun run,
                             std::shared_ptr<report::LutRequest> r) {
  auto* sub = lut.add_subcommand(name, help);
  sub->add_option("--size", r->size, "cells per axis (N×N; default 64)");
  sub->add_option("--out", r->out, out_help)->required();
  sub->add_option("--samples", r->samples, "quasi-Monte Carlo samples per cell")
      ->capture_default_str();
  sub->add_option("--threads", r->threads, "worker threads (0: all cores)")->capture_default_str();
  const std::string what = std::string("lut ") + name;
  sub->callback([&g, &selected, r, run, what] {
    selected = [&g, r, run, what] { return write_output(g, run(*r, progress_printer(g, what))); };
  });
  return sub;
}

}  // namespace

void add_lut(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* lut = app.add_subcommand(
      "lut", "pre-integrated GGX lookup tables: dfg | ltc-moments | ltc | energy");
  lut->require_subcommand(1);
  auto dfg = std::make_shared<report::LutRequest>();
  add_lut_subcommand(
      *lut, g, selected, "dfg",
      "the split-sum DFG table over (n·v, perceptual roughness): dfg1 = ∫(1−Fc)ρ cos, dfg2 = ∫Fc ρ "
      "cos, "
      "dfg_f82 = ∫μ(1−μ)^6 ρ cos; or Filament's multiscatter layout",
      "output file: .exr (RGB), .csv, .h (C++ header) or, with --layout filament, .inc (Filament's "
      "dfg.inc)",
      report::dfg_lut, dfg)
      ->add_option("--layout", dfg->layout,
                   "split-sum (R = dfg1, G = dfg2, B = dfg_f82) or filament (Filament's "
                   "multiscatter table: R = ∫Fc ρ "
                   "cos, G = ∫ρ cos, B = sheen; half-float RGB header, 128×128 by default)")
      ->capture_default_str();
  add_lut_subcommand(*lut, g, selected, "ltc-moments",
                     "LTC moments on the LTC grid: n_D = ∫ρ cos, f_D = ∫(1−v·h)^5 ρ cos, l_D = "
                     "∫(v·h)(1−v·h)^6 ρ cos",
                     "output file: .exr (RGB = n_D, f_D, l_D) or .csv", report::moments_lut,
                     std::make_shared<report::LutRequest>());
  add_lut_subcommand(
      *lut, g, selected, "ltc",
      "fit the LTC matrix of every cell with Ceres (Heitz et al. 2016) and write the two LTC "
      "textures",
      "output: FILE.exr writes FILE_1.exr (inverse matrix), FILE_2.exr (n_D, f_D, l_D, sphere form "
      "factor) and FILE.csv; FILE.csv writes the CSV only",
      report::ltc_lut, std::make_shared<report::LutRequest>());
  add_lut_subcommand(*lut, g, selected, "energy",
                     "Kulla-Conty energy compensation on the DFG grid: E(n·v, roughness) = ∫ρ cos "
                     "and E_avg(roughness) = 2∫E(μ)μ dμ",
                     "output file: .exr (R = E, G = E_avg), .csv or .h (C++ header)",
                     report::energy_lut, std::make_shared<report::LutRequest>());
}

}  // namespace fl::cli
