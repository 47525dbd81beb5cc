// `basis`: the data-driven Fresnel basis of the database's pages.
#include <fmt/format.h>

#include <chrono>
#include <memory>

#include "analysis/basis/basis.h"
#include "analysis/library/library.h"
#include "cli/app.h"
#include "jobs/basis_files.h"
#include "util/errors.h"

namespace fl::cli {

namespace {

// The command that made the files, as their headers quote it: the options that differ from the
// defaults.
std::string basis_command_line(const GlobalOptions& g, const std::vector<std::string>& globs,
                               const analysis::BasisOptions& o) {
  const analysis::BasisOptions defaults;
  std::string command = "fresnel-lab";
  if (g.min_coverage >= 0) command += fmt::format(" --min-coverage {:g}", g.min_coverage);
  command += " basis";
  for (const auto& glob : globs) command += " '" + glob + "'";
  if (o.construction != defaults.construction)
    command += fmt::format(" --construction {}", analysis::basis_construction_name(o.construction));
  if (o.data_terms != defaults.data_terms) command += fmt::format(" --terms {}", o.data_terms);
  if (o.poly_degree != defaults.poly_degree) command += fmt::format(" --degree {}", o.poly_degree);
  if (o.weighting != defaults.weighting)
    command += fmt::format(" --weighting {}", analysis::basis_weighting_name(o.weighting));
  if (o.weighting == analysis::BasisWeighting::Classes && o.metal_share != defaults.metal_share)
    command += fmt::format(" --metal-share {:g}", o.metal_share);
  if (o.rendered) command += " --rendered";
  return command;
}

// --construction, --weighting (returned, read in the callback), --metal-share and --rendered.
std::pair<std::shared_ptr<std::string>, std::shared_ptr<std::string>> add_construction_options(
    CLI::App* sub, analysis::BasisOptions& o) {
  auto construction = std::make_shared<std::string>(
      analysis::basis_construction_name(analysis::BasisOptions{}.construction));
  sub->add_option("--construction", *construction,
                  "optimized: b1..b4 chosen for each page's ΔE2000, starting from svd: b1 = "
                  "(1 - mu)^5 and b2.. the leading singular vectors of the residuals")
      ->capture_default_str()
      ->check(CLI::IsMember({"svd", "optimized"}));
  auto weighting = std::make_shared<std::string>(
      analysis::basis_weighting_name(analysis::BasisOptions{}.weighting));
  sub->add_option("--weighting", *weighting,
                  "how each page weighs in the construction: pages (alike), classes (metals and "
                  "the rest share --metal-share), perceptual (by ΔE2000 per unit reflectance)")
      ->capture_default_str()
      ->check(CLI::IsMember({"pages", "classes", "perceptual"}));
  sub->add_option("--metal-share", o.metal_share,
                  "with --weighting classes: the metals' share of the weight (0-1)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  sub->add_flag("--rendered", o.rendered,
                "also measure every projection as rendered (basis_rendered.csv)");
  return {construction, weighting};
}

}  // namespace

void add_basis_command(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand(
      "basis",
      "the data-driven Fresnel basis {1, b1, b2, ...}: from the spectral Fresnel curves of every "
      "page covering the visible range (SVD, then optimized for ΔE2000), polynomials in μ, a C++ "
      "header, projection errors per K (docs/basis.md)");
  struct Args {
    std::vector<std::string> globs;
    std::string out;
    analysis::BasisOptions options;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("GLOB", a->globs,
                  "page globs ('main/*/nk/*'; * within a path segment, ** across; default '**')");
  sub->add_option("--out", a->out, "output folder (created if missing; its parent must exist)")
      ->required()
      ->check(output_location());
  sub->add_option(
         "--terms", a->options.data_terms,
         "singular vectors after b1 (K = 2 to 2 + terms); the optimized construction needs 3")
      ->capture_default_str()
      ->check(CLI::Range(1, 8));
  sub->add_option("--degree", a->options.poly_degree, "degree of each term's polynomial in μ")
      ->capture_default_str()
      ->check(CLI::Range(1, 16));
  auto [construction, weighting] = add_construction_options(sub, a->options);
  sub->callback([&g, &selected, a, construction, weighting] {
    a->options.construction = analysis::basis_construction_from_name(*construction);
    a->options.weighting = analysis::basis_weighting_from_name(*weighting);
    if (a->options.construction == analysis::BasisConstruction::Optimized &&
        a->options.data_terms != 3)
      throw InputError(
          "basis: --construction optimized needs --terms 3 (its b2, b3, b4 start "
          "the optimization); use --construction svd for other counts");
    selected = [&g, a] {
      const auto t0 = std::chrono::steady_clock::now();
      analysis::LoadPolicy policy;
      policy.min_coverage = g.min_coverage >= 0 ? g.min_coverage : analysis::kDefaultMinCoverage;
      const std::vector<std::string> globs =
          a->globs.empty() ? std::vector<std::string>{"**"} : a->globs;
      const auto ctx = make_context(g);
      const auto set =
          analysis::load_materials(ctx, globs, policy, periodic_progress(g, "basis: reading "));
      if (set.materials.empty()) throw InputError("basis: no page covers the visible range");
      auto basis =
          analysis::build_basis(ctx, set, a->options, periodic_progress(g, "basis: building "));
      basis.min_coverage = policy.min_coverage;
      const std::string command = basis_command_line(g, a->globs, a->options);
      auto files = jobs::basis_files(ctx, basis, command);
      for (auto& f : files) f.first = a->out + "/" + f.first;
      io::write_files_atomic(files, a->out);
      progress(g,
               fmt::format(
                   "basis: {} of {} pages, {} skipped; wrote {} files to {} ({:.1f} s)",
                   basis.pages.size(), set.requested, set.skipped.size(), files.size(), a->out,
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()));
      return 0;
    };
  });
}

}  // namespace fl::cli
