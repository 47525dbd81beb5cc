#pragma once
// The exact Fresnel equations per channel: RGB η and κ.
#include <algorithm>
#include <array>
#include <vector>

#include "fresnel/derive.h"
#include "fresnel/exact.h"
#include "fresnel/exact_shader.h"
#include "fresnel/model_spec.h"
#include "fresnel/models/gulbrandsen.h"
#include "fresnel/unit.h"

namespace fl::fresnel::models {

struct FresnelRgb {
  static constexpr const char* kName = "fresnel_rgb";
  static constexpr const char* kLabel = "RGB Fresnel equations (eta, kappa)";
  // Wide enough for every page of the database: RGB η reaches 13.7 (main/Zn/nk/Querry), and no
  // material's η or κ in the visible comes near 10³.
  static constexpr std::array<ParamSpec, 2> kChannelParams{{
      {"eta", "relative index", ParamKind::Index, {0.01, 1000.0}, {0.01, kUnbounded}},
      {"kappa", "extinction", ParamKind::Extinction, {0.0, 1000.0}, {0.0, kUnbounded}},
  }};
  static constexpr std::array<ParamSpec, 0> kSharedParams{};
  static constexpr bool kCanLeaveUnitRange = false;
  static constexpr UnitFeatures kFeatures{.identifiable = true};
  // No table terms: exact conductor equations of a per-channel index.
  static constexpr ShaderCode kShader{kConductorHelpers,
                                      "  return fl_fresnel_conductor(cos_theta, eta, kappa);\n"};

  template <class T>
  static T channel(T cos_theta, const T* p, const T*) {
    return fresnel_conductor(cos_theta, p[0], p[1]);
  }
  // η, κ processed as reflectances.
  static std::vector<double> derive(const DeriveInput& in) {
    std::vector<double> p;
    for (int c = 0; c < 3; ++c)
      p.insert(p.end(), {in.derived.eta_refl[c], in.derived.kappa_refl[c]});
    return p;
  }
  // Gulbrandsen's η, κ for (F0, g) from both η derivations, and the point-sampled η, κ.
  static std::vector<std::vector<double>> extra_starts(const DeriveInput& in) {
    std::vector<std::vector<double>> s;
    for (const auto* g : {&in.derived.g_refl_eta, &in.derived.g_ps_eta}) {
      std::vector<double> p;
      for (int c = 0; c < 3; ++c) {
        const double eta = gulbrandsen_eta(in.derived.f0[c], std::clamp((*g)[c], 0.0, 1.0));
        p.insert(p.end(), {eta, gulbrandsen_kappa(in.derived.f0[c], eta)});
      }
      s.push_back(p);
    }
    std::vector<double> ps;
    for (int c = 0; c < 3; ++c) ps.insert(ps.end(), {in.derived.eta_ps[c], in.derived.kappa_ps[c]});
    s.push_back(ps);
    return s;
  }
  static std::vector<double> example() { return {0.18, 3.4, 0.42, 2.35, 1.37, 1.77}; }
};

}  // namespace fl::fresnel::models
