#include <fmt/format.h>

#include <chrono>
#include <filesystem>

#include "analysis/tables.h"
#include "cli/app.h"
#include "cli/table_registry.h"
#include "fresnel/model_set.h"
#include "report/writer.h"
#include "spectral/errors.h"

namespace fl::cli {

void add_lut(CLI::App& app, GlobalOptions& g, Runner& selected);  // cli/cmd_lut.cpp
void add_plot(CLI::App& app, GlobalOptions& g, Runner& selected);    // cli/cmd_plot.cpp
void add_render(CLI::App& app, GlobalOptions& g, Runner& selected);  // cli/cmd_plot.cpp
// The figures reproduce writes (relative path, bytes) and their Markdown gallery (cli/cmd_plot.cpp).
std::vector<std::pair<std::string, std::string>> reproduce_figures(const GlobalOptions& g, const analysis::Context& ctx,
                                                                   const std::vector<analysis::MaterialStudy>& studies,
                                                                   std::string& gallery_md);
void add_speed_command(CLI::App& app, GlobalOptions& g, Runner& selected);  // cli/cmd_speed.cpp
void add_plan_command(CLI::App& app, GlobalOptions& g, Runner& selected);   // cli/cmd_plan.cpp

namespace {

void add_materials(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand("materials", "list the catalog (name, class, data source)");
  auto format = std::make_shared<std::string>("csv");
  sub->add_option("--format", *format, "csv, md or json")->capture_default_str();
  sub->callback([&g, &selected, format] {
    selected = [&g, format] {
      const auto fmt_out = report::format_from_name(*format);
      analysis::Table t;
      t.name = "materials";
      t.title = "Material catalog";
      t.columns = {{"key"}, {"material"}, {"class"}, {"source"}, {"reference"}};
      for (const auto& m : spectral::read_catalog(g.settings.paths))
        t.rows.push_back({m.key, m.name, std::string(spectral::to_string(m.material_class)), m.source, m.reference});
      fmt::print("{}", report::render(t, fmt_out));
      return 0;
    };
  });
}

void add_curve(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand("curve", "per-angle ground truth RGB, model RGB and ΔE2000 (CSV)");
  auto material = std::make_shared<std::string>();
  auto model = std::make_shared<std::string>("schlick");
  auto format = std::make_shared<std::string>("csv");
  auto params = std::make_shared<std::string>("derived");
  std::string models;
  for (const auto& m : fresnel::model_specs()) models += (models.empty() ? "" : ", ") + std::string(m.name);
  sub->add_option("MATERIAL", *material, "catalog name, database page (main/Au/nk/Johnson) or file")->required();
  sub->add_option("--model", *model, "Fresnel model: " + models)->capture_default_str();
  sub->add_option("--params", *params, "derived (from the spectral procedure) or fitted (Ceres)")->capture_default_str();
  sub->add_option("--format", *format, "csv, md or json")->capture_default_str();
  sub->callback([&g, &selected, material, model, format, params] {
    selected = [&g, material, model, format, params] {
      const auto f = report::format_from_name(*format);
      const auto ctx = make_context(g);
      const auto m = analysis::load_material(ctx, spectral::resolve_material(*material, g.settings.paths));
      print_warnings(g, {m});
      fmt::print("{}", report::render(analysis::curve_table(ctx, m, *model, *params), f));
      return 0;
    };
  });
}

void add_table(CLI::App& app, GlobalOptions& g, Runner& selected) {
  std::string names;
  for (const auto& t : table_specs()) names += (names.empty() ? "" : " | ") + std::string(t.name);
  auto* sub = app.add_subcommand("table", "one report table to stdout: " + names);
  auto name = std::make_shared<std::string>();
  auto format = std::make_shared<std::string>("csv");
  sub->add_option("NAME", *name, names)->required();
  sub->add_option("--format", *format, "csv, md or json")->capture_default_str();
  sub->add_option("--blend-weight", g.blend.weight, "blend tables: share of the second material")->capture_default_str();
  sub->add_option("--blend-chain", g.blend.chain, "blend tables: materials per blend (2 = pairs; N blends N consecutive metals)")
      ->capture_default_str();
  sub->callback([&g, &selected, name, format] {
    selected = [&g, name, format] {
      const auto& spec = find_table(*name);
      const auto f = report::format_from_name(*format);
      const auto ctx = make_context(g);
      const auto ms = analysis::load_catalog(ctx);
      print_warnings(g, ms);
      TableInputs in(ctx, ms, g);
      fmt::print("{}", report::render(spec.build(in), f));
      return 0;
    };
  });
}

void add_presets(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand("presets", "F0, F82, g, eta, kappa per catalog material in the working space");
  auto format = std::make_shared<std::string>("csv");
  auto openpbr = std::make_shared<bool>(false);
  sub->add_option("--format", *format, "csv, md, json, or mtlx (a MaterialX document)")->capture_default_str();
  sub->add_flag("--openpbr", *openpbr, "the OpenPBR form: base_color = F0, specular_color = F82 tint");
  sub->callback([&g, &selected, format, openpbr] {
    selected = [&g, format, openpbr] {
      if (*format != "mtlx") report::format_from_name(*format);  // validate before the work
      const auto ctx = make_context(g);
      const auto ms = analysis::load_catalog(ctx);
      print_warnings(g, ms);
      TableInputs in(ctx, ms, g);
      if (*format == "mtlx") {
        fmt::print("{}", analysis::presets_materialx(ctx, in.studies()));
        return 0;
      }
      const auto t = *openpbr ? analysis::openpbr_table(ctx, in.studies()) : analysis::presets_table(ctx, in.studies());
      fmt::print("{}", report::render(t, report::format_from_name(*format)));
      return 0;
    };
  });
}

void add_reproduce(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand("reproduce", "every table as DIR/NAME.csv and DIR/NAME.md, plus DIR/README.md");
  auto out = std::make_shared<std::string>();
  sub->add_option("--out", *out, "output folder (created if missing)")->required();
  auto no_figures = std::make_shared<bool>(false);
  sub->add_flag("--no-figures", *no_figures, "skip DIR/figures/ (colour strips and curve plots per material)");
  sub->callback([&g, &selected, out, no_figures] {
    selected = [&g, out, no_figures] {
      const auto ctx = make_context(g);
      const auto ms = analysis::load_catalog(ctx);
      print_warnings(g, ms);
      // Everything is computed before anything is written, so a failure leaves no partial set.
      std::vector<std::pair<std::string, std::string>> files;
      std::string index = "# Fresnel Lab reports\n\nGenerated by `fresnel-lab reproduce`. Every table is a CSV "
                          "(machine-readable, SPEC §6 columns) and a Markdown file.\n\n| table | what it shows | files |\n|---|---|---|\n";
      TableInputs in(ctx, ms, g);
      for (const auto& spec : table_specs()) {
        if (!spec.in_reproduce) continue;
        const auto t0 = std::chrono::steady_clock::now();
        const auto t = spec.build(in);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        progress(g, fmt::format("reproduce: {} ({} rows, {:.2f} s)", spec.name, t.rows.size(), s));
        files.emplace_back(std::string(spec.name) + ".csv", report::to_csv(t));
        files.emplace_back(std::string(spec.name) + ".md", report::to_markdown(t));
        index += fmt::format("| {} | {} | [{}.md]({}.md), [{}.csv]({}.csv) |\n", spec.name, spec.summary, spec.name,
                             spec.name, spec.name, spec.name);
      }
      files.emplace_back("presets.json", report::to_json(analysis::presets_table(ctx, in.studies())));
      files.emplace_back("presets.mtlx", analysis::presets_materialx(ctx, in.studies()));
      index += "| presets (JSON, MaterialX) | the presets as JSON, and a MaterialX document with one "
               "generalized_schlick_bsdf per material | [presets.json](presets.json), [presets.mtlx](presets.mtlx) |\n";
      if (!*no_figures) {  // issue 7: DIR/figures/ and the gallery DIR/figures.md
        std::string gallery;
        for (auto& f : reproduce_figures(g, ctx, in.studies(), gallery)) files.push_back(std::move(f));
        files.emplace_back("figures.md", gallery);
        index += "| figures | colour strips and reflectance / ΔE2000 curves per material (PNG) | [figures.md](figures.md) |\n";
      }
      const auto& st = g.settings;
      index += fmt::format("\nSettings: space {}, illuminant {}, {} adaptation, {} angles, {:g} nm steps.\n", st.space,
                           st.illuminant, st.adaptation, st.angles, st.step_nm);
      files.emplace_back("README.md", index);
      for (auto& f : files) f.first = *out + "/" + f.first;
      report::write_files_atomic(files);
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
  };
  return table;
}

}  // namespace fl::cli
