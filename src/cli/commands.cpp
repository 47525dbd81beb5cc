#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/consensus/trusted.h"
#include "analysis/presets/preset_tables.h"
#include "analysis/tables/table_registry.h"
#include "analysis/tables/tables.h"
#include "cli/app.h"
#include "documents/materialx.h"
#include "documents/preset_formats.h"
#include "documents/table_formats.h"
#include "fresnel/registered_models.h"
#include "io/writer.h"
#include "jobs/reproduce.h"
#include "util/errors.h"

namespace fl::cli {

void add_lut(CLI::App& app, GlobalOptions& g, Runner& selected);              // cli/cmd_lut.cpp
void add_plot(CLI::App& app, GlobalOptions& g, Runner& selected);             // cli/cmd_plot.cpp
void add_render(CLI::App& app, GlobalOptions& g, Runner& selected);           // cli/cmd_plot.cpp
void add_speed_command(CLI::App& app, GlobalOptions& g, Runner& selected);    // cli/cmd_speed.cpp
void add_plan_command(CLI::App& app, GlobalOptions& g, Runner& selected);     // cli/cmd_plan.cpp
void add_pages_command(CLI::App& app, GlobalOptions& g, Runner& selected);    // cli/cmd_library.cpp
void add_library_command(CLI::App& app, GlobalOptions& g, Runner& selected);  // cli/cmd_library.cpp
void add_shader_command(CLI::App& app, GlobalOptions& g, Runner& selected);   // cli/cmd_shader.cpp
void add_basis_command(CLI::App& app, GlobalOptions& g, Runner& selected);    // cli/cmd_basis.cpp

// `presets --consensus`: cli/cmd_library.cpp.
int consensus_presets(GlobalOptions& g, const std::vector<std::string>& specs,
                      const documents::PresetFormat& format, bool openpbr, const std::string& out,
                      double roughness);
void add_consensus_command(CLI::App& app, GlobalOptions& g, Runner& selected);

namespace {

void add_materials(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand("materials", "list the catalog (name, class, data source)");
  auto format = std::make_shared<std::string>("csv");
  sub->add_option("--format", *format, "csv, md or json")->capture_default_str();
  sub->callback([&g, &selected, format] {
    selected = [&g, format] {
      const auto f = documents::format_from_name(*format);
      fmt::print("{}", documents::render(analysis::catalog_table(g.settings.paths), f));
      return 0;
    };
  });
}

void add_curve(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand(
      "curve",
      "per material and angle: ground truth RGB, the model's RGB and ΔE2000, with the material's "
      "coverage and the fit's flags (CSV, Markdown or JSON on stdout)");
  auto materials = std::make_shared<std::vector<std::string>>();
  auto model = std::make_shared<std::string>("schlick");
  auto format = std::make_shared<std::string>("csv");
  auto params = std::make_shared<std::string>("derived");
  sub->add_option("MATERIALS", *materials, kMaterialsHelp)->required();
  sub->add_option("--model", *model, "Fresnel model: " + fresnel::model_names())
      ->capture_default_str();
  sub->add_option("--params", *params,
                  "derived (the spectral procedure), fitted (to the curve) or rendered (to the "
                  "render under IBL and area lights)")
      ->capture_default_str();
  sub->add_option("--format", *format, "csv, md or json")->capture_default_str();
  sub->callback([&g, &selected, materials, model, format, params] {
    selected = [&g, materials, model, format, params] {
      const auto f = documents::format_from_name(*format);
      analysis::parameter_set_from_name(*params);
      const auto ctx = make_context(g);
      const auto ms = load_many(g, ctx, *materials);
      fmt::print("{}", documents::render(analysis::curve_table(ctx, ms, *model, *params), f));
      return 0;
    };
  });
}

void add_table(CLI::App& app, GlobalOptions& g, Runner& selected) {
  std::string names;
  for (const auto& t : analysis::table_specs())
    names += (names.empty() ? "" : " | ") + std::string(t.name);
  auto* sub = app.add_subcommand("table", "one report table to stdout: " + names);
  auto name = std::make_shared<std::string>();
  auto materials = std::make_shared<std::vector<std::string>>();
  auto format = std::make_shared<std::string>("csv");
  sub->add_option("NAME", *name, names)->required();
  sub->add_option("MATERIALS", *materials, std::string(kMaterialsHelp) + "; default: the catalog");
  sub->add_option("--format", *format, "csv, md or json")->capture_default_str();
  sub->add_option("--blend-weight", g.blend.weight, "blend tables: share of the second material")
      ->capture_default_str();
  sub->add_option("--blend-chain", g.blend.chain,
                  "blend tables: materials per blend (2 = pairs; N blends N consecutive metals)")
      ->capture_default_str();
  sub->callback([&g, &selected, name, materials, format] {
    selected = [&g, name, materials, format] {
      const auto& spec = analysis::find_table(*name);
      const auto f = documents::format_from_name(*format);
      const auto ctx = make_context(g);
      const auto ms = load_many(g, ctx, *materials);
      analysis::TableInputs in(ctx, ms, g.blend, study_progress(g, "fitting: "));
      fmt::print("{}", documents::render(spec.build(in), f));
      return 0;
    };
  });
}

// The presets of `specs` in `format` (documents/preset_formats.h).
std::string preset_documents(GlobalOptions& g, const std::vector<std::string>& specs,
                             const documents::PresetFormat& format, bool openpbr, int basis_terms,
                             double roughness) {
  const auto ctx = make_context(g);
  analysis::ExportOptions options;
  options.roughness = roughness;
  const auto named = analysis::named_materials(ctx, specs, [&](const std::vector<std::string>& s) {
    return load_many(g, ctx, s, &options.skipped, true);
  });
  if (named.materials.empty())
    throw InputError("no material left to work on (every one was skipped)");
  for (const auto& note : named.notes) progress(g, note);
  const auto& ms = named.materials;
  if (format.kind != documents::PresetKind::Table) {
    // Documents use the derived parameters only: no fits.
    analysis::StudyOptions derived_only;
    derived_only.fit = false;
    const auto studies =
        analysis::study_materials(ctx, ms, derived_only, study_progress(g, "deriving: "));
    if (format.kind == documents::PresetKind::MaterialX &&
        !documents::materialx_space(ctx).note.empty())
      progress(g, "presets: " + documents::materialx_space(ctx).note);
    return documents::preset_document(format, {ctx, studies, Table{}, options});
  }
  const auto studies = analysis::study_materials(ctx, ms, analysis::presets_study_options(openpbr),
                                                 study_progress(g, "fitting: "));
  auto t = openpbr ? analysis::openpbr_table(ctx, studies)
                   : analysis::presets_table(ctx, studies, basis_terms);
  for (const auto& m : ms)
    if (!m.resolved.empty()) t.notes.push_back(m.resolved);
  if (!options.skipped.empty())
    t.notes.push_back(
        fmt::format("skipped {}: {}", options.skipped.size(), fmt::join(options.skipped, "; ")));
  return documents::preset_document(format, {ctx, studies, t, options});
}

void add_presets(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub =
      app.add_subcommand("presets", "F0, F82, g, eta, kappa per material in the working space");
  struct Args {
    std::string format = "csv", shader, out;
    bool openpbr = false;
    int basis = 0;  // 0: not given
    double roughness = analysis::kDefaultExportRoughness;
    std::vector<std::string> materials, consensus;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("MATERIALS", a->materials,
                  std::string(kMaterialsHelp) +
                      "; a metal's short name (gold, Ti) gives the element's trusted value: the "
                      "consensus of its bulk pages where enough agree, else the recommended page; "
                      "default: the catalog (the talk's pages)");
  sub->add_option("--format", a->format,
                  "csv, md, json, mtlx (a MaterialX document) or gltf (glTF 2.0 materials)")
      ->capture_default_str();
  sub->add_flag("--openpbr", a->openpbr,
                "the OpenPBR Surface form (csv, md, json; with mtlx: open_pbr_surface)");
  sub->add_option("--shader", a->shader,
                  "mtlx only: generalized_schlick (default), open_pbr_surface or standard_surface");
  sub->add_option("--out", a->out,
                  "write to FILE (atomically: complete or not at all) instead of standard output")
      ->check(output_location());
  sub->add_option("--basis", a->basis,
                  "csv, md, json: the coefficients of basis3, basis4 (default) or basis5 (K = 3, "
                  "4, 5)")
      ->check(CLI::Range(3, 5));
  sub->add_option("--roughness", a->roughness,
                  "mtlx, gltf: every material's perceptual roughness (specular_roughness, "
                  "roughnessFactor; alpha = r^2 for the generalized Schlick BSDF)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  sub->add_option("--consensus", a->consensus,
                  "consensus presets instead, with their uncertainty: an element ('Au', 'gold'), a "
                  "page glob, or NAME=GLOB[,GLOB...] (repeatable; docs/consensus.md)");
  sub->callback([&g, &selected, a] {
    const auto* format = &documents::preset_format(a->format, a->openpbr, a->shader);
    if (!a->consensus.empty()) {
      if (!a->materials.empty())
        throw InputError("presets: name MATERIALS or --consensus, not both");
      selected = [&g, a, format] {
        return consensus_presets(g, a->consensus, *format, a->openpbr, a->out, a->roughness);
      };
      return;
    }
    if (a->basis != 0 && (format->kind != documents::PresetKind::Table || a->openpbr))
      throw InputError("presets: --basis applies to the csv, md and json presets only");
    selected = [&g, a, format] {
      emit(g, a->out,
           preset_documents(g, a->materials, *format, a->openpbr,
                            a->basis != 0 ? a->basis : analysis::kPresetBasisTerms, a->roughness));
      return 0;
    };
  });
}

// The look-dev contact sheets scripts/lookdev.sh left in OUT/lookdev/ (sorted, relative to OUT).
std::vector<std::string> lookdev_sheets(const std::string& out) {
  namespace fs = std::filesystem;
  std::vector<std::string> sheets;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(fs::path(out) / "lookdev", ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() > 10 && name.ends_with(".sheet.png")) sheets.push_back("lookdev/" + name);
  }
  std::sort(sheets.begin(), sheets.end());
  return sheets;
}

void add_reproduce(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand(
      "reproduce",
      "the report: every table as DIR/NAME.csv and .md, the presets in every preset format, "
      "index.html, the figures and flips (unless --no-figures) and README.md");
  auto out = std::make_shared<std::string>();
  sub->add_option("--out", *out, "output folder (created if missing; its parent must exist)")
      ->required()
      ->check(output_location());
  auto no_figures = std::make_shared<bool>(false);
  sub->add_flag("--no-figures", *no_figures,
                "skip DIR/figures/ (colour strips and curve plots per material)");
  sub->callback([&g, &selected, out, no_figures] {
    selected = [&g, out, no_figures] {
      const auto ctx = make_context(g);
      const auto ms = analysis::load_catalog(ctx);
      print_warnings(g, ms);
      std::optional<draw::LabelFont> font;  // the figures' labels
      if (!*no_figures) font.emplace(g.label_font);
      analysis::TableInputs in(ctx, ms, g.blend, study_progress(g, "fitting: "));
      auto files = jobs::reproduce_files(
          in, font ? &*font : nullptr, [&g](const std::string& line) { progress(g, line); },
          lookdev_sheets(*out));
      for (auto& f : files) f.first = *out + "/" + f.first;
      io::write_files_atomic(files, *out);
      progress(g, fmt::format("reproduce: wrote {} files to {}", files.size(), *out));
      return 0;
    };
  });
}

}  // namespace

const std::vector<Command>& commands() {
  static const std::vector<Command> table{
      {"materials", add_materials},
      {"curve", add_curve},
      {"presets", add_presets},
      {"table", add_table},
      {"reproduce", add_reproduce},
      {"lut", add_lut},
      {"plot", add_plot},
      {"render", add_render},
      {"speed", add_speed_command},
      {"plan", add_plan_command},
      {"pages", add_pages_command},
      {"library", add_library_command},
      {"consensus", add_consensus_command},
      {"shader", add_shader_command},
      {"basis", add_basis_command},
  };
  return table;
}

}  // namespace fl::cli
