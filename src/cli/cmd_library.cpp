// `pages`: the database's pages; `library`: presets of every page matching globs, with flags.
#include <fmt/format.h>

#include <chrono>
#include <memory>

#include "analysis/library/library.h"
#include "cli/app.h"
#include "documents/table_formats.h"
#include "jobs/library_files.h"
#include "spectral/errors.h"

namespace fl::cli {

void add_pages_command(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand("pages",
                                 "list database pages: book, class (from the data), visible "
                                 "coverage of n and k, reference, status");
  struct Args {
    std::vector<std::string> globs;
    std::string format = "csv";
  };
  auto a = std::make_shared<Args>();
  sub->add_option("GLOB", a->globs,
                  "page globs ('main/*/nk/*'; * within a path segment, ** across; default '**')");
  sub->add_option("--format", a->format, "csv, md or json")->capture_default_str();
  sub->callback([&g, &selected, a] {
    selected = [&g, a] {
      const auto f = report::format_from_name(a->format);
      const auto ctx = make_context(g);
      fmt::print("{}", report::render(analysis::pages_table(
                                          ctx, a->globs, periodic_progress(g, "pages: reading ")),
                                      f));
      return 0;
    };
  });
}

namespace {

std::optional<spectral::MaterialClass> class_option(const std::string& name) {
  if (name == "metal") return spectral::MaterialClass::Metal;
  if (name == "dielectric") return spectral::MaterialClass::Dielectric;
  if (name == "all") return std::nullopt;
  throw InputError(fmt::format("--class must be metal, dielectric or all, not '{}'", name));
}

}  // namespace

void add_library_command(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand("library",
                                 "presets of every database page matching globs (default: every "
                                 "conductor page covering the visible range): "
                                 "every model derived and fitted, quality flags, CSV/MD/JSON, "
                                 "MaterialX, spread table, gallery");
  struct Args {
    std::vector<std::string> globs;
    std::string out, cls = "metal";
    bool strict = false, no_gallery = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("GLOB", a->globs,
                  "page globs ('main/*/nk/*'; * within a path segment, ** across; default '**')");
  sub->add_option("--out", a->out, "output folder (created if missing)")->required();
  sub->add_option("--class", a->cls, "metal (conductors, from the data), dielectric or all")
      ->capture_default_str();
  sub->add_flag("--strict", a->strict,
                "fail on the first page that cannot be read instead of skipping it");
  sub->add_flag("--no-gallery", a->no_gallery, "skip gallery.md and its strips/");
  sub->callback([&g, &selected, a] {
    selected = [&g, a] {
      analysis::LibraryOptions o;
      o.only = class_option(a->cls);
      if (!a->globs.empty()) o.globs = a->globs;
      if (g.min_coverage >= 0) o.min_coverage = g.min_coverage;
      o.strict = a->strict;
      const auto t0 = std::chrono::steady_clock::now();
      const auto ctx = make_context(g);
      const auto lib = analysis::build_library(ctx, o, periodic_progress(g, "library: reading "),
                                               periodic_progress(g, "library: fitting "));
      std::string command = "fresnel-lab";
      if (g.min_coverage >= 0) command += fmt::format(" --min-coverage {:g}", g.min_coverage);
      command += " library";
      for (const auto& glob : o.globs) command += " '" + glob + "'";
      command += " --class " + a->cls + (a->strict ? " --strict" : "");
      auto files = report::library_files(ctx, lib, !a->no_gallery, command);
      for (auto& f : files) f.first = a->out + "/" + f.first;
      report::write_files_atomic(files);
      progress(
          g,
          fmt::format(
              "library: {} of {} pages in the library, {} skipped; wrote {} files to {} ({:.1f} s)",
              lib.studies.size(), lib.set.requested, lib.set.skipped.size(), files.size(), a->out,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()));
      return 0;
    };
  });
}

}  // namespace fl::cli
