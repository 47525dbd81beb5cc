// `lut dfg | ltc-moments | ltc | energy`: pre-integrated GGX lookup tables as EXR textures, CSV
// and C/C++ headers.
#include <fmt/format.h>

#include <chrono>
#include <memory>

#include "analysis/pipeline/context.h"
#include "cli/app.h"
#include "fresnel/table_terms.h"
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

using LutRun = io::Output (*)(const jobs::LutRequest&, const analysis::LutProgress&);

// After the files: the error as rendered of the tables just written (the tables' own share, over
// the catalog's metals), unless quiet.
void report_table_error(const GlobalOptions& g, const jobs::LutRequest& r,
                        analysis::Lighting lighting, const std::string& what) {
  if (g.quiet) return;
  const auto ctx = make_context(g);
  const auto ms = analysis::load_catalog(ctx);
  analysis::StudyOptions derived_only;
  derived_only.fit = false;
  derived_only.method_errors = false;
  const auto studies = analysis::study_materials(ctx, ms, derived_only);
  progress(g, what + ": " + jobs::table_error_line(ctx, studies, r, lighting));
}

CLI::App* add_lut_subcommand(CLI::App& lut, GlobalOptions& g, Runner& selected, const char* name,
                             const std::string& help, const char* out_help, LutRun run,
                             std::shared_ptr<jobs::LutRequest> r) {
  auto* sub = lut.add_subcommand(name, help);
  sub->add_option("--size", r->size, "cells per axis (N×N; default 64)");
  sub->add_option("--out", r->out, out_help)->required()->check(output_location());
  sub->add_option("--samples", r->samples, "quasi-Monte Carlo samples per cell")
      ->capture_default_str();
  sub->add_option("--threads", r->threads, "worker threads (0: all cores)")->capture_default_str();
  sub->add_option("--symbol", r->symbol,
                  "with .h output: the C symbol of the arrays (NAME_data, NAME_SIZE, "
                  "NAME_CHANNELS; a further texture adds _2, _3, ...)");
  sub->add_option_function<std::string>(
         "--storage", [r](const std::string& s) { r->half = s == "half"; },
         "texel storage: float (32-bit) or half (EXR HALF channels; .h: uint16_t half-float bit "
         "patterns); default float")
      ->check(CLI::IsMember({"float", "half"}, CLI::ignore_case));
  const std::string what = std::string("lut ") + name;
  const std::string table = name;
  sub->callback([&g, &selected, r, run, what, table] {
    selected = [&g, r, run, what, table] {
      const int status = write_output(g, run(*r, progress_printer(g, what)));
      if (status == 0 && table == "dfg" && r->layout == "split-sum")
        report_table_error(g, *r, analysis::Lighting::Ibl, what);
      if (status == 0 && (table == "ltc" || table == "ltc-moments"))
        report_table_error(g, *r, analysis::Lighting::Area, what);
      return status;
    };
  });
  return sub;
}

// "dfg1, dfg2, dfg_f82, ..." or the LTC moments "n_d, f_d, l_d, ...": the table terms' channels.
std::string term_channels(bool dfg) {
  std::string s;
  for (const auto& t : fresnel::kTermRegistry)
    s += fmt::format("{}{} (∫{} ρ cos)", s.empty() ? "" : ", ", dfg ? t.dfg.channel : t.ltc.channel,
                     t.formula);
  return s;
}

}  // namespace

void add_lut(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* lut = app.add_subcommand(
      "lut", "pre-integrated GGX lookup tables: dfg | ltc-moments | ltc | energy");
  lut->require_subcommand(1);
  auto dfg = std::make_shared<jobs::LutRequest>();
  add_lut_subcommand(*lut, g, selected, "dfg",
                     "the split-sum DFG table over (n·v, perceptual roughness), one channel per "
                     "table term: " +
                         term_channels(true) +
                         ", dfg1 stored less dfg2 (the split sum's scale); or Filament's "
                         "multiscatter layout",
                     "output file: .exr (RGB per texture: FILE.exr, FILE_2.exr, ...), .csv, .h "
                     "(a C/C++ header per texture: FILE.h, FILE_2.h, ...) or, with --layout "
                     "filament, .inc (Filament's dfg.inc)",
                     jobs::dfg_lut, dfg)
      ->add_option("--layout", dfg->layout,
                   "split-sum (every table term) or filament (Filament's "
                   "multiscatter table: R = ∫Fc ρ "
                   "cos, G = ∫ρ cos, B = sheen; half-float RGB header, 128×128 by default)")
      ->capture_default_str();
  add_lut_subcommand(*lut, g, selected, "ltc-moments",
                     "LTC moments on the LTC grid, one per table term: " + term_channels(false),
                     "output file: .exr (RGB per texture: FILE.exr = n_d, f_d, l_d; FILE_3.exr, "
                     "...), .h (a C/C++ header per texture: FILE.h, FILE_3.h, ...) or .csv",
                     jobs::moments_lut, std::make_shared<jobs::LutRequest>());
  add_lut_subcommand(
      *lut, g, selected, "ltc",
      "fit the LTC matrix of every cell with Ceres (Heitz et al. 2016) and write the LTC "
      "textures",
      "output: FILE.exr writes FILE_1.exr (inverse matrix), FILE_2.exr (n_d, f_d, l_d, sphere form "
      "factor), FILE_3.exr, ... (the other table terms' moments) and FILE.csv; FILE.h writes "
      "FILE_1.h, FILE_2.h, ... (C/C++ headers of the same textures); FILE.csv writes the CSV only",
      jobs::ltc_lut, std::make_shared<jobs::LutRequest>());
  auto energy = std::make_shared<jobs::LutRequest>();
  auto* energy_cmd = add_lut_subcommand(
      *lut, g, selected, "energy",
      "Kulla-Conty energy compensation on the DFG grid: E(n·v, roughness) = ∫ρ cos and "
      "E_avg(roughness) = 2∫E(μ)μ dμ; with --dielectric, the same with the exact dielectric "
      "Fresnel reflectance F(v·h, η) in the integral, per η-slice",
      "output file: .exr or .h (a C/C++ header; R = E, G = E_avg; --dielectric: an atlas of "
      "η-slices, RGBA = E_F(η), E_F,avg(η), E_F(1/η), E_F,avg(1/η)), or .csv",
      jobs::energy_lut, energy);
  auto* dielectric = energy_cmd->add_flag(
      "--dielectric", energy->dielectric,
      "the dielectric table: E_F(n·v, roughness, η) = ∫F(v·h, η) ρ cos "
      "(reflection only) and its average, at η and 1/η, for K slices uniform in "
      "F0^¼ from F0 = 0 (η = 1) to 0.25 (η = 3)");
  energy_cmd
      ->add_option("--slices", energy->slices,
                   "with --dielectric: η-slices, a square number from 4 to 64 (the atlas is "
                   "√K × √K tiles)")
      ->capture_default_str()
      ->needs(dielectric);
}

}  // namespace fl::cli
