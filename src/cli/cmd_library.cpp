// `pages`: the database's pages; `library`: presets of every page matching globs, with flags.
#include <fmt/format.h>

#include <chrono>
#include <memory>

#include "analysis/consensus/consensus.h"
#include "analysis/library/library.h"
#include "analysis/presets/preset_tables.h"
#include "cli/app.h"
#include "documents/preset_formats.h"
#include "documents/table_formats.h"
#include "jobs/library_files.h"
#include "util/errors.h"
#include "util/suggest.h"

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
      const auto f = documents::format_from_name(a->format);
      const auto ctx = make_context(g);
      fmt::print(
          "{}",
          documents::render(
              analysis::pages_table(ctx, a->globs, periodic_progress(g, "pages: reading ")), f));
      return 0;
    };
  });
}

namespace {

// The file that marks a folder `library` wrote, so a rerun may replace it.
constexpr const char* kLibraryMarker = ".fresnel-lab-library";

std::optional<spectral::MaterialClass> class_option(const std::string& name) {
  const std::vector<NameChoice> choices = {
      {"metal", {"metals", "conductor"}}, {"dielectric", {"dielectrics"}}, {"all", {}}};
  const auto match = match_name(name, choices);
  if (!match) throw InputError("--class: " + unknown_name_message("class", name, choices));
  if (*match == "metal") return spectral::MaterialClass::Metal;
  if (*match == "dielectric") return spectral::MaterialClass::Dielectric;
  return std::nullopt;
}

}  // namespace

void add_library_command(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub =
      app.add_subcommand("library",
                         "presets of every database page matching MATERIALS (default: every "
                         "conductor page covering the visible range): "
                         "every model derived and fitted, quality flags, CSV/MD/JSON, "
                         "MaterialX, glTF, spread table, gallery");
  struct Args {
    std::vector<std::string> globs;
    std::string out, cls = "metal";
    bool strict = false, no_gallery = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("MATERIALS", a->globs,
                  "database pages (main/Au/nk/Johnson), page globs ('main/*/nk/*'; * within a "
                  "path segment, ** across; default '**'), catalog names (gold) or files (as for "
                  "presets); those not of --class are skipped with the reason");
  sub->add_option("--out", a->out,
                  "output folder, replaced as a whole (new, empty, or one `library` wrote)")
      ->required()
      ->check(output_location());
  sub->add_option("--class", a->cls, "metal (conductors, from the data), dielectric or all")
      ->capture_default_str();
  sub->add_flag("--strict", a->strict,
                "fail on the first page that cannot be read instead of skipping it");
  sub->add_flag("--no-gallery", a->no_gallery, "skip gallery.md and its strips/");
  sub->callback([&g, &selected, a] {
    io::require_replaceable_folder(a->out, kLibraryMarker);
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
      const auto files = jobs::library_files(ctx, lib, !a->no_gallery, command);
      io::replace_folder_atomic(a->out, files, kLibraryMarker);
      progress(
          g,
          fmt::format(
              "library: {} of {} pages in the library, {} skipped; wrote {} files to {} ({:.1f} s)",
              lib.set.materials.size(), lib.set.requested, lib.set.skipped.size(), files.size(),
              a->out,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()));
      return 0;
    };
  });
}

namespace {

std::vector<analysis::ConsensusRequest> requests_of(const GlobalOptions& g,
                                                    const std::vector<std::string>& specs) {
  std::vector<analysis::ConsensusRequest> out;
  for (const auto& spec : specs) out.push_back(analysis::consensus_request(g.settings.paths, spec));
  return out;
}

}  // namespace

int consensus_presets(GlobalOptions& g, const std::vector<std::string>& specs,
                      const documents::PresetFormat& format, bool openpbr, const std::string& out,
                      double roughness) {
  const bool document = format.kind != documents::PresetKind::Table;
  if (!out.empty()) require_output_folder(out);
  const auto requests = requests_of(g, specs);
  const auto ctx = make_context(g);
  analysis::StudyOptions options = analysis::presets_study_options(openpbr || document);
  const auto c =
      analysis::consensus_for(ctx, requests, options, periodic_progress(g, "consensus: reading "));
  Table t;
  if (!document) {
    t = openpbr ? analysis::openpbr_table(ctx, c.set.studies)
                : analysis::presets_table(ctx, c.set.studies);
    analysis::add_uncertainty_columns(t, c.set);
  }
  analysis::ExportOptions exported;
  exported.roughness = roughness;
  emit(g, out, documents::preset_document(format, {ctx, c.set.studies, t, exported}));
  return 0;
}

void add_consensus_command(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand(
      "consensus",
      "consensus of the bulk measurements per element or group: F0/F82, uncertainty, every "
      "page's distance, outliers, recommended page; or published presets against it");
  struct Args {
    std::vector<std::string> specs;
    std::string table = "groups", format = "csv", peers;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("GROUP", a->specs,
                  "an element ('Au', 'gold'), a page glob, or NAME=GLOB[,GLOB...]; default: every "
                  "metal group of the database ('**')");
  sub->add_option("--table", a->table,
                  "groups (one row per group), pages (every page's distance), kinds (outliers per "
                  "page kind) or peers (published presets, with --peers)")
      ->capture_default_str();
  sub->add_option("--peers", a->peers,
                  "folder of physicallybased.csv, physicallybased_pages.csv, openpbr_examples.csv");
  sub->add_option("--format", a->format, "csv, md or json")->capture_default_str();
  sub->callback([&g, &selected, a] {
    if (a->table != "groups" && a->table != "pages" && a->table != "kinds" && a->table != "peers")
      throw InputError("--table must be groups, pages, kinds or peers, not '" + a->table + "'");
    if ((a->table == "peers") != !a->peers.empty())
      throw InputError("--peers DIR goes with --table peers (and only with it)");
    selected = [&g, a] {
      const auto f = documents::format_from_name(a->format);
      const auto ctx = make_context(g);
      const auto read = periodic_progress(g, "consensus: reading ");
      if (a->table == "peers") {
        fmt::print("{}", documents::render(analysis::peer_table(ctx, a->peers, read), f));
        return 0;
      }
      analysis::StudyOptions derived_only;
      derived_only.fit = false;
      derived_only.method_errors = false;
      analysis::RequestedConsensus c;
      if (a->specs.empty()) {
        c.pages = analysis::study_pages(ctx, {"**"}, read);
        c.set =
            analysis::build_consensus(ctx, analysis::page_groups(c.pages.studies), derived_only);
      } else {
        c = analysis::consensus_for(ctx, requests_of(g, a->specs), derived_only, read);
      }
      const auto t = a->table == "groups"  ? analysis::consensus_table(ctx, c.set)
                     : a->table == "pages" ? analysis::consensus_pages_table(c.set)
                                           : analysis::outlier_kinds_table(c.set);
      fmt::print("{}", documents::render(t, f));
      return 0;
    };
  });
}

}  // namespace fl::cli
