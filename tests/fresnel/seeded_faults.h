#pragma once
// The faults scripts/check-model-unit.sh seeds: each a unit deriving from a copied unit U with one
// member replaced. The check writes this file into its scratch copy's src/fresnel/models/faults.h,
// followed by the faulty units it registers; nothing else includes it.
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "fresnel/model_spec.h"
#include "fresnel/registry.h"
#include "fresnel/unit.h"

namespace fl::fresnel::models::seeded {

// Compile-time text: "0.97 * (" + s + ")" and a body with every `return X;` as
// `return 0.97 * (X);`.
template <std::size_t N>
struct Text {
  char s[N]{};
};
constexpr std::size_t length(const char* s) {
  std::size_t n = 0;
  while (s[n]) ++n;
  return n;
}
constexpr const char* kScale = "0.97 * (";
constexpr std::size_t count_returns(const char* s) {
  std::size_t n = 0;
  for (std::size_t i = 0; s[i]; ++i)
    n += s[i] == 'r' && s[i + 1] == 'e' && s[i + 2] == 't' && s[i + 3] == 'u' && s[i + 4] == 'r' &&
         s[i + 5] == 'n' && s[i + 6] == ' ';
  return n;
}
template <std::size_t N>
constexpr Text<N> scaled_returns(const char* s) {
  Text<N> t;
  std::size_t o = 0;
  bool open = false;
  for (std::size_t i = 0; s[i]; ++i) {
    t.s[o++] = s[i];
    if (i >= 6 && s[i] == ' ' && s[i - 1] == 'n' && s[i - 2] == 'r' && s[i - 3] == 'u' &&
        s[i - 4] == 't' && s[i - 5] == 'e' && s[i - 6] == 'r') {
      for (const char* p = kScale; *p; ++p) t.s[o++] = *p;
      open = true;
    }
    if (open && s[i + 1] == ';') t.s[o++] = ')', open = false;
  }
  return t;
}
template <std::size_t N>
constexpr Text<N> scaled(const char* s) {
  Text<N> t;
  std::size_t o = 0;
  for (const char* p = kScale; *p; ++p) t.s[o++] = *p;
  for (std::size_t i = 0; s[i]; ++i) t.s[o++] = s[i];
  t.s[o++] = ')';
  return t;
}
constexpr ShaderCode with_body(ShaderCode c, const char* body) {
  c.body = body;
  return c;
}

template <class U>
struct GlslFault : U {
  static constexpr const char* kBody = U::kShader.body;
  static constexpr auto kScaledBody =
      scaled_returns<length(kBody) + 9 * count_returns(kBody) + 1>(kBody);
  static constexpr ShaderCode kShader = with_body(U::kShader, kScaledBody.s);
};

template <class U>
struct KernelFault : GlslFault<U> {
  template <class T>
  static T channel(T cos_theta, const T* p, const T* shared) {
    return T(0.97) * U::channel(cos_theta, p, shared);
  }
  template <class T>
  static T channel_unclamped(T cos_theta, const T* p,
                             const T* shared) requires(U::kFeatures.output_clamp) {
    return T(0.97) * U::channel_unclamped(cos_theta, p, shared);
  }
  template <class T, class P>
  static T channel_at(T cos_theta, const P& prepared) requires(U::kFeatures.prepared_channel) {
    return T(0.97) * U::channel_at(cos_theta, prepared);
  }
};

template <std::size_t N>
constexpr std::array<TermWeight, N> with_first(std::span<const TermWeight> w, const char* first) {
  std::array<TermWeight, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = w[i];
  out[0].glsl = first;
  return out;
}

template <class U>
struct TablesFault : U {
  static constexpr std::size_t kN = std::size(U::kTableTerms);
  static constexpr const char* kWeight = U::kTableTerms[0].glsl;
  static constexpr auto kFirst = scaled<length(kWeight) + 10>(kWeight);
  static constexpr std::array<TermWeight, kN> kTableTerms =
      with_first<kN>(U::kTableTerms, kFirst.s);
};

template <class U>
struct AverageFault : U {
  static double average(const double* p, const double* shared) {
    return U::average(p, shared) + 0.01;
  }
};

template <class U>
struct DeriveFault : U {
  static std::vector<double> derive(const DeriveInput& in) {
    auto p = U::derive(in);
    for (std::size_t c = 0; c < 3; ++c) p[c * U::kChannelParams.size()] *= 0.9;
    return p;
  }
};

}  // namespace fl::fresnel::models::seeded
