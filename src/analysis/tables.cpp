#include "analysis/tables.h"

#include <fmt/format.h>

#include "fresnel/models.h"
#include "spectral/errors.h"

namespace fl::analysis {

namespace {

std::vector<color::Rgb> schlick_curve(const Context& ctx, const color::Rgb& f0) {
  std::vector<color::Rgb> out;
  for (double c : ctx.cos_thetas())
    out.push_back({fresnel::schlick(c, f0.r), fresnel::schlick(c, f0.g), fresnel::schlick(c, f0.b)});
  return out;
}

std::string setting_note(const Context& ctx) {
  const auto& s = ctx.settings();
  return fmt::format("Working space {}, illuminant {}, {} adaptation, CIE 1931 2° observer, {:g}-{:g} nm at {:g} nm, "
                     "{} angles over 0-90°, outside medium η = {:g}.",
                     s.space, s.illuminant, s.adaptation, ctx.grid().start_nm, ctx.grid().end_nm(),
                     ctx.grid().step_nm, s.angles, s.eta_outside);
}

}  // namespace

Table schlick_table(const Context& ctx, const std::vector<LoadedMaterial>& materials) {
  Table t;
  t.name = "schlick";
  t.title = "Schlick against spectral ground truth (ΔE2000)";
  t.columns = {{"material"}, {"class"}, {"source"}, {"rms_de00", 3}, {"mean_de00", 3}, {"max_de00", 3}};
  for (const auto& m : materials) {
    const auto truth = ground_truth_curve(ctx, m.ior, ctx.settings().eta_outside);
    const auto e = curve_error(ctx, truth, schlick_curve(ctx, truth.front()));
    t.rows.push_back({m.material.name, std::string(spectral::to_string(m.material.material_class)),
                      m.material.source, e.rms, e.mean, e.max});
  }
  t.reading =
      "Schlick's model with F0 taken from the spectral ground truth at normal incidence, per material. "
      "Metals with a strongly coloured grazing tint (chromium, zinc, iron) are where Schlick is weakest.";
  t.notes = {setting_note(ctx), "ΔE2000 per Sharma, Wu & Dalal 2005; RMS, mean and max over the incidence angles."};
  return t;
}

Table curve_table(const Context& ctx, const LoadedMaterial& m, const std::string& model) {
  if (model != "schlick") throw InputError(fmt::format("unknown model '{}'", model));
  const auto truth = ground_truth_curve(ctx, m.ior, ctx.settings().eta_outside);
  const auto approx = schlick_curve(ctx, truth.front());
  const auto de = de2000_per_angle(ctx, truth, approx);
  Table t;
  t.name = "curve";
  t.title = fmt::format("{}: ground truth and {} per angle", m.material.name, model);
  t.columns = {{"theta_deg", 2}, {"truth_r", 6}, {"truth_g", 6}, {"truth_b", 6},
               {"model_r", 6},   {"model_g", 6}, {"model_b", 6}, {"de00", 4}};
  for (size_t i = 0; i < truth.size(); ++i)
    t.rows.push_back({ctx.angles_deg()[i], truth[i].r, truth[i].g, truth[i].b, approx[i].r, approx[i].g,
                      approx[i].b, de[i]});
  t.notes = {setting_note(ctx)};
  return t;
}

}  // namespace fl::analysis
