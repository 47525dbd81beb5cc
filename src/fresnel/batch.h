#pragma once
// Batched evaluation of a Fresnel model over an array of incidence cosines (the cost side of
// `table speed`): each model's inner loop is its plain scalar kernel over contiguous arrays, which
// the compiler can vectorize. One "evaluation" in Fresnel Lab's cost figures is one RGB value at
// one angle (three channels).
#include <cstddef>

#include "fresnel/registered_models.h"

namespace fl::fresnel {

// One RGB value of model m at one angle (flat parameter layout), in double or in float.
inline color::Rgb evaluate_rgb(Model m, double cos_theta, const double* params) {
  return model_spec(m).evaluate(cos_theta, params, false);
}
inline color::RgbT<float> evaluate_rgb(Model m, float cos_theta, const float* params) {
  return model_spec(m).evaluate_float(cos_theta, params);
}

// Evaluates model m (flat parameter layout) at the n cosines; writes planar RGB: out[0..n) red,
// out[n..2n) green, out[2n..3n) blue.
inline void evaluate_batch(Model m, const float* params, const float* cos_theta, std::size_t n,
                           float* out) {
  model_spec(m).batch_float(params, cos_theta, n, out);
}
inline void evaluate_batch(Model m, const double* params, const double* cos_theta, std::size_t n,
                           double* out) {
  model_spec(m).batch_double(params, cos_theta, n, out);
}

}  // namespace fl::fresnel
