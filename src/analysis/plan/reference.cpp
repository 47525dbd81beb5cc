#include "analysis/plan/reference.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/shader/shader.h"
#include "color/lab.h"
#include "fresnel/registered_models.h"

namespace fl::analysis {

namespace {

// n·v at the shading view angles and the grazing edge, from 1 down.
std::vector<double> reference_novs() {
  std::vector<double> out;
  for (double deg : kShadingViewDeg) out.push_back(std::cos(deg * std::numbers::pi / 180.0));
  out.push_back(kReferenceMinNov);
  return out;
}

// The material's roughness values and the tables' edges 0 and 1, ascending, once each.
std::vector<double> reference_roughness(const std::vector<double>& roughness) {
  std::vector<double> out = roughness;
  out.push_back(0.0);
  out.push_back(1.0);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<Column> reference_columns() {
  std::vector<Column> cols{{"material"},
                           {"model"},
                           {"parameters"},
                           {"lighting"},
                           {"function"},
                           {"nov", 9, true, true},
                           {"roughness", 9, true, true}};
  for (const char* what : {"engine", "truth"})
    for (const char* c : {"r", "g", "b"})
      cols.push_back({fmt::format("{}_{}", what, c), 9, true, true});
  cols.push_back({"de00", 4});
  return cols;
}

// "f0_r=0.955000 f0_g=…" as the rows use them.
std::string parameter_text(const ReferenceMaterial& m) {
  const auto names = fresnel::model_spec(m.model).param_names();
  std::string out;
  for (size_t i = 0; i < names.size(); ++i)
    out += fmt::format("{}{}={:.{}f}", i ? " " : "", names[i], m.params[i], kPlanParamDecimals);
  return out;
}

void add_row(Table& t, const Context& ctx, const ReferenceMaterial& m, Lighting l, bool at_nov,
             double nov, double roughness, const color::Rgb& engine, const color::Rgb& truth) {
  std::vector<Cell> row{m.material->material.name,
                        std::string(fresnel::model_spec(m.model).name),
                        parameter_text(m),
                        std::string(lighting_name(l)),
                        shader_function_name(m.model, at_nov ? Lighting::Punctual : l),
                        nov};
  row.push_back(at_nov ? Cell{std::string()} : Cell{roughness});
  for (const auto* rgb : {&engine, &truth})
    for (int c = 0; c < 3; ++c) row.push_back((*rgb)[c]);
  row.push_back(color::ciede2000(ctx.rgb_to_lab(truth), ctx.rgb_to_lab(engine)));
  t.rows.push_back(std::move(row));
}

// The model at n·v against the spectral curve there (punctual lights, mirrors).
void add_at_nov(Table& t, const Context& ctx, const ReferenceMaterial& m, Lighting l) {
  for (double nov : reference_novs())
    add_row(t, ctx, m, l, true, nov, 0.0,
            fresnel::model_spec(m.model).evaluate(nov, m.params.data(), false),
            ground_truth_rgb(ctx, m.material->ior, nov, ctx.settings().eta_outside));
}

// fresnel_NAME_ibl / _area at every (n·v, roughness) against the lobe's spectral integral.
void add_lobe(Table& t, const Context& ctx, const ReferenceMaterial& m, Lighting l,
              const EngineTables& tables) {
  std::vector<NovRoughness> at;
  for (double r : reference_roughness(m.roughness))
    for (double nov : reference_novs()) at.push_back({nov, r});
  const auto points = shading_points_at(at, false, 0, tables);
  const auto truth = lobe_truth(ctx, *m.material, points);
  for (size_t k = 0; k < points.size(); ++k)
    add_row(t, ctx, m, l, false, points[k].nov, points[k].roughness,
            engine_shading(m.model, m.params, l, points[k]), truth[k]);
}

}  // namespace

Table reference_table(const Context& ctx, const std::vector<ReferenceMaterial>& materials,
                      const std::vector<Lighting>& lightings, const EngineTables& tables) {
  Table t;
  t.name = "reference";
  t.title = "Reference values for a port: the shipped functions from the shipped tables";
  t.columns = reference_columns();
  for (auto m : materials)
    for (Lighting l : lightings) {
      for (double& x : m.params) x = std::stod(fmt::format("{:.{}f}", x, kPlanParamDecimals));
      if (l == Lighting::Punctual || m.mirror)
        add_at_nov(t, ctx, m, l);
      else
        add_lobe(t, ctx, m, l, tables);
    }
  return t;
}

Table plan_reference(const Context& ctx, const std::vector<MaterialStudy>& studies, const Plan& p) {
  const auto& sc = p.scene_choice();
  std::vector<ReferenceMaterial> materials;
  for (const auto& g : sc.groups)
    for (size_t k : g.materials) {
      const auto& c = sc.materials.at(k);
      materials.push_back({studies.at(k).material, c.model, c.params, c.roughness,
                           p.scene.materials.at(k).mirror()});
    }
  return reference_table(ctx, materials, p.scene.lightings(),
                         engine_tables(p.tables.size, p.tables.storage));
}

Table model_reference(const Context& ctx, const std::vector<LoadedMaterial>& materials,
                      fresnel::Model model, Lighting lighting, std::vector<double> roughness,
                      const EngineTables& tables) {
  if (roughness.empty()) roughness.assign(kDefaultRoughness.begin(), kDefaultRoughness.end());
  StudyOptions options;
  options.fit = false;
  const auto studies = study_materials(ctx, materials, options);
  std::vector<ReferenceMaterial> refs;
  for (size_t k = 0; k < materials.size(); ++k) {
    const bool mirror =
        std::all_of(roughness.begin(), roughness.end(), [](double r) { return r == 0; });
    refs.push_back({&materials[k], model, studies[k].result(model).derived, roughness, mirror});
  }
  return reference_table(ctx, refs, {lighting}, tables);
}

}  // namespace fl::analysis
