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

void add_basis_command(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand(
      "basis",
      "the data-driven Fresnel basis {1, (1 − μ)⁵, b2, ...}: SVD of the spectral Fresnel curves "
      "of every page covering the visible range, polynomials in μ, a C++ header, projection "
      "errors per K (docs/basis.md)");
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
  sub->add_option("--terms", a->options.data_terms, "data-driven terms (K = 2 + terms)")
      ->capture_default_str()
      ->check(CLI::Range(1, 8));
  sub->add_option("--degree", a->options.poly_degree, "degree of each term's polynomial in μ")
      ->capture_default_str()
      ->check(CLI::Range(1, 16));
  sub->add_option("--metal-share", a->options.metal_share,
                  "the metals' share of the construction's weight, 0-1 (each class's pages weigh "
                  "the same within it); -1: every page weighs the same")
      ->capture_default_str()
      ->check(CLI::Range(-1.0, 1.0));
  sub->add_option("--normalize", a->options.normalize_power, "normalization power")
      ->capture_default_str();
  sub->add_flag("--perceptual", a->options.perceptual, "perceptual");
  sub->callback([&g, &selected, a] {
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
      std::string command = "fresnel-lab";
      if (g.min_coverage >= 0) command += fmt::format(" --min-coverage {:g}", g.min_coverage);
      command += " basis";
      for (const auto& glob : a->globs) command += " '" + glob + "'";
      if (a->options.data_terms != analysis::BasisOptions{}.data_terms)
        command += fmt::format(" --terms {}", a->options.data_terms);
      if (a->options.poly_degree != analysis::BasisOptions{}.poly_degree)
        command += fmt::format(" --degree {}", a->options.poly_degree);
      if (a->options.metal_share != analysis::BasisOptions{}.metal_share)
        command += fmt::format(" --metal-share {:g}", a->options.metal_share);
      auto files = report::basis_files(ctx, basis, command);
      for (auto& f : files) f.first = a->out + "/" + f.first;
      report::write_files_atomic(files, a->out);
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
