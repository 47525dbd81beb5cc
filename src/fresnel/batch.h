#pragma once
// Batched evaluation of a Fresnel model over an array of incidence cosines (issue 6: the cost
// side of `table speed`). The model switch is taken once per call, outside the loops, so each
// model's inner loop is its plain scalar kernel (models.h) over contiguous arrays, which the
// compiler can vectorize. Pure functions, templated on the scalar (float and double).
#include <cstddef>

#include "fresnel/model_set.h"

namespace fl::fresnel {

namespace detail {
// out[c·n + i] = kernel(cos_theta[i], channel c's parameters, shared parameters).
// The parameters are copied to locals first, so the compiler knows the output cannot alias them.
constexpr int kMaxBatchParams = 4;  // per channel and shared: at most 3 in model_set.h
template <class T, class Kernel>
void batch_channels(const T* params, int per_channel, int n_shared, const T* cos_theta, std::size_t n, T* out,
                    Kernel kernel) {
  T shared[kMaxBatchParams] = {};
  for (int k = 0; k < n_shared; ++k) shared[k] = params[3 * per_channel + k];
  for (int c = 0; c < 3; ++c) {
    T p[kMaxBatchParams] = {};
    for (int k = 0; k < per_channel; ++k) p[k] = params[c * per_channel + k];
    T* __restrict o = out + static_cast<std::size_t>(c) * n;
    for (std::size_t i = 0; i < n; ++i) o[i] = kernel(cos_theta[i], p, shared);
  }
}
}  // namespace detail

// Evaluates model `m` (flat parameter layout of model_set.h, `per_channel` parameters per
// channel) at the n cosines; writes planar RGB: out[0..n) red, out[n..2n) green, out[2n..3n) blue.
// One "evaluation" in Fresnel Lab's cost figures is one RGB value at one angle (three channels).
template <class T>
void evaluate_batch(Model m, int per_channel, const T* params, const T* cos_theta, std::size_t n, T* out) {
  using detail::batch_channels;
  const int n_shared = static_cast<int>(model_spec(m).shared_params.size());
  switch (m) {
    case Model::Schlick:
      return batch_channels(params, per_channel, n_shared, cos_theta, n, out,
                            [](T c, const T* p, const T*) { return schlick(c, p[0]); });
    case Model::GeneralizedSchlick:
      return batch_channels(params, per_channel, n_shared, cos_theta, n, out,
                            [](T c, const T* p, const T*) { return generalized_schlick(c, p[0], p[1], p[2]); });
    case Model::CookTorrance:
      return batch_channels(params, per_channel, n_shared, cos_theta, n, out,
                            [](T c, const T* p, const T* s) { return cook_torrance(c, p[0], s[0], s[1]); });
    case Model::Lazanyi:
      return batch_channels(params, per_channel, n_shared, cos_theta, n, out,
                            [](T c, const T* p, const T*) { return lazanyi(c, p[0], p[1], p[2]); });
    case Model::F82:
      return batch_channels(params, per_channel, n_shared, cos_theta, n, out,
                            [](T c, const T* p, const T*) { return hoffman_f82(c, p[0], p[1]); });
    case Model::Gulbrandsen:
      return batch_channels(params, per_channel, n_shared, cos_theta, n, out,
                            [](T c, const T* p, const T*) { return gulbrandsen(c, p[0], p[1]); });
    case Model::FresnelRgb:
      return batch_channels(params, per_channel, n_shared, cos_theta, n, out,
                            [](T c, const T* p, const T*) { return fresnel_conductor(c, p[0], p[1]); });
  }
}

}  // namespace fl::fresnel
