// `speed`: the cost-against-error table with its plot, from the committed costs or timed live.
#include <fmt/format.h>

#include <memory>
#include <optional>

#include "analysis/speed/speed.h"
#include "analysis/tables/table_registry.h"
#include "cli/app.h"
#include "documents/table_formats.h"
#include "draw/speed_plot.h"
#include "io/writer.h"

namespace fl::cli {

void add_speed_command(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand("speed",
                                 "every Fresnel model's cost per evaluation against its ΔE2000 "
                                 "error (table speed), with a plot");
  struct Args {
    std::string format = "csv", costs, gpu_costs, plot;
    bool measure = false;
    std::vector<std::string> materials;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("MATERIALS", a->materials,
                  std::string(kMaterialsHelp) + "; default: the catalog");
  sub->add_option("--format", a->format, "csv, md or json")->capture_default_str();
  sub->add_option(
      "--costs", a->costs,
      "model costs file (default $FRESNEL_LAB_COSTS or the tool's bench/model_costs.csv)");
  sub->add_option(
      "--gpu-costs", a->gpu_costs,
      "GPU costs file (default $FRESNEL_LAB_GPU_COSTS or the tool's bench/gpu_costs.csv)");
  sub->add_flag(
      "--measure", a->measure,
      "time the batched kernels now instead of reading the costs file (not reproducible)");
  sub->add_option("--plot", a->plot,
                  "also write the error-against-cost plot to this file (.png, .svg or .pdf)")
      ->check(output_location());
  sub->callback([&g, &selected, a] {
    selected = [&g, a] {
      const auto f = documents::format_from_name(a->format);
      if (!a->plot.empty()) draw::file_type(a->plot);
      const auto costs =
          a->measure ? analysis::measure_model_costs()
                     : analysis::load_model_costs(given_or(a->costs, g.settings.paths.model_costs));
      const auto ctx = make_context(g);
      const auto ms = load_many(g, ctx, a->materials);
      std::optional<draw::LabelFont> font;
      if (!a->plot.empty()) font.emplace(g.label_font);
      analysis::TableInputs in(ctx, ms, g.blend, study_progress(g, "fitting: "));
      const auto gpu = analysis::load_gpu_costs(given_or(a->gpu_costs, g.settings.paths.gpu_costs));
      const auto t = analysis::speed_table(ctx, in.studies(), costs, gpu);
      if (!a->plot.empty()) {
        draw::write_speed_plot(a->plot, analysis::speed_rows(in.studies(), costs, gpu), *font);
        progress(g, "speed: wrote " + a->plot);
      }
      fmt::print("{}", documents::render(t, f));
      return 0;
    };
  });
}

}  // namespace fl::cli
