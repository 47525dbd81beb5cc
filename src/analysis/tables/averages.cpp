#include "analysis/tables/averages.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/study/table_notes.h"
#include "fresnel/average.h"
#include "fresnel/registry.h"
#include "util/quantile.h"

namespace fl::analysis {

namespace {

// The ground truth is smooth in μ (no (1 − μ)^p endpoint of the exponent models): 8 panels of 20
// nodes agree with 64 panels to 1e-12 on the catalog.
constexpr int kTruthPanels = 8;

double max_abs_difference(const color::Rgb& a, const color::Rgb& b) {
  double d = 0;
  for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a[c] - b[c]));
  return d;
}

std::vector<Cell> averages_row(const MaterialStudy& s, const ModelResult& r, bool fitted,
                               const color::Rgb& truth) {
  const auto& params = fitted ? r.fitted.parameters : r.derived;
  const color::Rgb f = fresnel::hemispherical_average(r.model, params);
  const bool closed = fresnel::average_in_closed_form(r.model, params);
  return {s.material->material.name,
          std::string(spectral::to_string(s.material->material.material_class)),
          std::string(fresnel::model_spec(r.model).name),
          std::string(fitted ? "fitted" : "derived"),
          f[0],
          f[1],
          f[2],
          truth[0],
          truth[1],
          truth[2],
          max_abs_difference(f, truth),
          std::string(closed ? "closed form" : "quadrature")};
}

// "schlick 0.0123 / 0.0045, ...": per model the median over materials of the largest channel
// difference, derived / fitted.
std::string median_differences(const Table& t) {
  const int model = column_index(t, "model"), kind = column_index(t, "parameters"),
            diff = column_index(t, "max_abs_difference");
  std::map<std::string, std::vector<double>> by[2];
  std::vector<std::string> order;
  for (const auto& row : t.rows) {
    const auto& name = std::get<std::string>(row[model]);
    if (std::find(order.begin(), order.end(), name) == order.end()) order.push_back(name);
    by[std::get<std::string>(row[kind]) == "fitted"][name].push_back(std::get<double>(row[diff]));
  }
  std::string out;
  for (const auto& name : order)
    out += fmt::format("{}{} {:.5f} / {:.5f}", out.empty() ? "" : ", ", name, median(by[0][name]),
                       median(by[1][name]));
  return out;
}

}  // namespace

color::Rgb ground_truth_average(const Context& ctx, const spectral::ComplexIorSpectrum& ior) {
  const double eta_outside = ctx.settings().eta_outside;
  return fresnel::hemispherical_average_of(
      [&](double mu) { return ground_truth_rgb(ctx, ior, mu, eta_outside); }, kTruthPanels);
}

Table averages_table(const Context& ctx, const std::vector<MaterialStudy>& studies) {
  Table t;
  t.name = "averages";
  t.title = "Hemispherical averages F_avg = 2∫F(μ)μ dμ of every model against the ground truth";
  t.columns = {{"material"},
               {"class"},
               {"model"},
               {"parameters"},
               {"f_avg_r", 5},
               {"f_avg_g", 5},
               {"f_avg_b", 5},
               {"truth_r", 5},
               {"truth_g", 5},
               {"truth_b", 5},
               {"max_abs_difference", 5},
               {"method"}};
  for (const auto& s : studies) {
    const color::Rgb truth = ground_truth_average(ctx, s.material->ior);
    for (const auto& r : s.models)
      for (const bool fitted : {false, true})
        if (!fitted || !r.fitted.parameters.empty())  // studies without fits have none
          t.rows.push_back(averages_row(s, r, fitted, truth));
  }
  t.reading = fmt::format(
      "Kulla–Conty's multiple-scattering term scales by F_avg²·E_avg / (1 − F_avg·(1 − E_avg)), so "
      "a "
      "model's F_avg error reaches the rendered colour wherever the lobe is rough. Median over the "
      "materials of the largest channel difference from the ground truth, derived / fitted: {}.",
      median_differences(t));
  t.notes = {setting_note(ctx),
             "f_avg: the model's hemispherical average per channel in the working space; truth: "
             "the spectral ground truth's (the reflectance spectrum averaged over μ, then through "
             "the colour pipeline).",
             "method: the unit's closed form where it has one and its output clamp leaves the "
             "curve unchanged, Gauss–Legendre quadrature of the kernel otherwise.",
             "E_avg(α), the other half of the compensation, is the lut energy table's."};
  return t;
}

}  // namespace fl::analysis
