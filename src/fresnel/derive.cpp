#include "fresnel/derive.h"

#include <algorithm>
#include <cmath>

namespace fl::fresnel {

DerivedParameters derive_parameters(const std::vector<color::Rgb>& w, const color::Mat3& rgb_to_xyz,
                                    const spectral::ComplexIorSpectrum& ior_absolute, double eta_outside,
                                    const std::array<double, 3>& ps_nm) {
  spectral::ComplexIorSpectrum ior = ior_absolute;
  for (auto& v : ior.ior) v /= eta_outside;
  DerivedParameters d;
  d.f0 = spectral_reflectance_rgb(w, ior, 1.0, 1.0);
  d.f82 = spectral_reflectance_rgb(w, ior, kCosTheta82, 1.0);
  const auto ps = point_sample(ior, ps_nm);
  d.eta_ps = ps.eta;
  d.kappa_ps = ps.kappa;
  d.eta_refl = process_as_reflectance(w, ior, false);
  d.kappa_refl = process_as_reflectance(w, ior, true);
  for (int c = 0; c < 3; ++c) {
    d.f82_tint[c] = d.f82[c] / schlick(kCosTheta82, d.f0[c]);
    d.g_refl_eta[c] = gulbrandsen_g(d.f0[c], d.eta_refl[c]);
    d.g_ps_eta[c] = gulbrandsen_g(d.f0[c], d.eta_ps[c]);
  }
  d.eta_rep = (rgb_to_xyz * d.eta_refl).Y;
  d.kappa_rep = (rgb_to_xyz * d.kappa_refl).Y;
  return d;
}

std::vector<double> gulbrandsen_params(const color::Rgb& f0, const color::Rgb& g, int* clamped) {
  std::vector<double> p;
  for (int c = 0; c < 3; ++c) {
    const double gc = std::clamp(g[c], 0.0, 1.0);
    if (clamped && gc != g[c]) ++*clamped;
    p.push_back(f0[c]);
    p.push_back(gc);
  }
  return p;
}

std::vector<double> derived_model_params(Model m, const DerivedParameters& d) {
  std::vector<double> p;
  switch (m) {
    case Model::Schlick:
      return {d.f0.r, d.f0.g, d.f0.b};
    case Model::GeneralizedSchlick:
      for (int c = 0; c < 3; ++c) {
        // F82 = F0 + (1 − F0)(6/7)^p  ⇒  p = ln((F82 − F0)/(1 − F0)) / ln(6/7); Schlick's 5 when
        // the measured curve dips below F0 there.
        const double t = (d.f82[c] - d.f0[c]) / (1.0 - d.f0[c]);
        const double pc = t > 0.0 && t < 1.0 ? std::log(t) / std::log(1.0 - kCosTheta82) : 5.0;
        p.insert(p.end(), {d.f0[c], 1.0, std::clamp(pc, 0.5, 30.0)});
      }
      return p;
    case Model::CookTorrance:
      return {d.f0.r, d.f0.g, d.f0.b, d.eta_rep, d.kappa_rep};
    case Model::Lazanyi:
      for (int c = 0; c < 3; ++c) p.insert(p.end(), {d.f0[c], f82_coefficient(d.f0[c], d.f82[c]), 6.0});
      return p;
    case Model::F82:
      for (int c = 0; c < 3; ++c) p.insert(p.end(), {d.f0[c], d.f82[c]});
      return p;
    case Model::Gulbrandsen:
      return gulbrandsen_params(d.f0, d.g_refl_eta);
    case Model::FresnelRgb:
      for (int c = 0; c < 3; ++c) p.insert(p.end(), {d.eta_refl[c], d.kappa_refl[c]});
      return p;
  }
  return p;
}

}  // namespace fl::fresnel
