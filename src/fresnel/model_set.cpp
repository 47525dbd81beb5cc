#include "fresnel/model_set.h"

#include <algorithm>
#include <fmt/format.h>

#include "spectral/errors.h"

namespace fl::fresnel {

std::vector<std::string> ModelSpec::param_names() const {
  std::vector<std::string> out;
  for (const char* c : {"r", "g", "b"})
    for (const auto& p : channel_params) out.push_back(p + "_" + c);
  for (const auto& p : shared_params) out.push_back(p);
  return out;
}

std::vector<ParamRange> ModelSpec::bounds() const {
  std::vector<ParamRange> out;
  for (int c = 0; c < 3; ++c) out.insert(out.end(), channel_bounds.begin(), channel_bounds.end());
  out.insert(out.end(), shared_bounds.begin(), shared_bounds.end());
  return out;
}

const std::vector<ModelSpec>& model_specs() {
  // Fit bounds: reflectances in [0, 1] (F0 < 1 where Gulbrandsen's mapping is singular),
  // exponents where the curves stay monotone enough to be meaningful, indices covering every
  // catalog material with margin (η from 0.01, κ up to 20).
  static const std::vector<ModelSpec> specs{
      {Model::Schlick, "schlick", "Schlick", {"f0"}, {}, {{0.0, 1.0}}, {}, false},
      {Model::GeneralizedSchlick, "generalized_schlick", "Generalized Schlick (F0, F90, p)", {"f0", "f90", "p"}, {},
       {{0.0, 1.0}, {0.0, 1.5}, {0.5, 30.0}}, {}, true},
      {Model::CookTorrance, "cook_torrance", "Cook-Torrance colour interpolation", {"f0"}, {"eta_rep", "kappa_rep"},
       {{0.0, 1.0}}, {{0.01, 10.0}, {0.0, 20.0}}, false},
      {Model::Lazanyi, "lazanyi", "Lazanyi 2005 (F0, a, alpha)", {"f0", "a", "alpha"}, {},
       {{0.0, 1.0}, {-10.0, 30.0}, {1.0, 20.0}}, {}, true},
      {Model::F82, "f82", "Hoffman 2019 F82 (F0, F82)", {"f0", "f82"}, {}, {{0.0, 1.0}, {0.0, 1.0}}, {}, false},
      {Model::Gulbrandsen, "gulbrandsen", "Gulbrandsen 2014 (F0, g)", {"f0", "g"}, {},
       {{0.0, kGulbrandsenMaxR}, {0.0, 1.0}}, {}, false},
      {Model::FresnelRgb, "fresnel_rgb", "RGB Fresnel equations (eta, kappa)", {"eta", "kappa"}, {},
       {{0.01, 10.0}, {0.0, 20.0}}, {}, false},
  };
  return specs;
}

const ModelSpec& model_spec(Model m) {
  for (const auto& s : model_specs())
    if (s.model == m) return s;
  throw std::logic_error("unknown model");
}

const ModelSpec& model_from_name(const std::string& name) {
  std::string known;
  for (const auto& s : model_specs()) {
    if (name == s.name) return s;
    known += (known.empty() ? "" : ", ") + std::string(s.name);
  }
  throw InputError(fmt::format("unknown model '{}' (expected one of: {})", name, known));
}

std::vector<color::Rgb> evaluate_curve(Model m, const std::vector<double>& params,
                                       const std::vector<double>& cos_thetas) {
  const int pc = model_spec(m).per_channel();
  std::vector<color::Rgb> out;
  out.reserve(cos_thetas.size());
  for (double c : cos_thetas) out.push_back(evaluate_rgb<double>(m, pc, c, params.data()));
  return out;
}

std::vector<color::Rgb> evaluate_curve_unclamped(Model m, const std::vector<double>& params,
                                                 const std::vector<double>& cos_thetas) {
  if (m != Model::F82) return evaluate_curve(m, params, cos_thetas);
  std::vector<color::Rgb> out;
  for (double c : cos_thetas) {
    color::Rgb v;
    for (int ch = 0; ch < 3; ++ch) v[ch] = hoffman_f82_unclamped(c, params[2 * ch], params[2 * ch + 1]);
    out.push_back(v);
  }
  return out;
}

int reflectances_outside_unit(Model m, const std::vector<double>& params) {
  const auto& spec = model_spec(m);
  const int pc = spec.per_channel();
  int n = 0;
  for (int j = 0; j < pc; ++j) {
    const auto& name = spec.channel_params[j];
    if (name != "f0" && name != "f82" && name != "f90") continue;
    for (int ch = 0; ch < 3; ++ch) n += params[ch * pc + j] < 0.0 || params[ch * pc + j] > 1.0;
  }
  return n;
}

int clamp_to_domain(Model m, std::vector<double>& p) {
  int moved = 0;
  auto clamp = [&](double& v, double lo, double hi) {
    const double c = std::clamp(v, lo, hi);
    moved += c != v;
    v = c;
  };
  constexpr double kHuge = 1e300;
  for (int ch = 0; ch < 3; ++ch) {
    switch (m) {
      case Model::Gulbrandsen:
        clamp(p[2 * ch], 0.0, kGulbrandsenMaxR);
        clamp(p[2 * ch + 1], 0.0, 1.0);
        break;
      case Model::FresnelRgb:
        clamp(p[2 * ch], 0.01, kHuge);
        clamp(p[2 * ch + 1], 0.0, kHuge);
        break;
      case Model::GeneralizedSchlick:
      case Model::Lazanyi:
        clamp(p[3 * ch + 2], 0.01, kHuge);
        break;
      default:
        break;
    }
  }
  return moved;
}

bool f82_model_clamps(const std::vector<double>& params, const std::vector<double>& cos_thetas) {
  for (double c : cos_thetas)
    for (int ch = 0; ch < 3; ++ch) {
      const double f = hoffman_f82_unclamped(c, params[2 * ch], params[2 * ch + 1]);
      if (f < 0.0 || f > 1.0) return true;
    }
  return false;
}

}  // namespace fl::fresnel
