#pragma once
// Arithmetic helpers that stay differentiable under Ceres Jets and stay in the scalar's precision.
#include <cmath>

namespace fl::color {

// sqrt whose derivative stays finite at 0 (a Jet would give 0·∞ = NaN there). Below 1e-200 the
// value is 0 in double; in float the threshold rounds to 0, so only x ≤ 0 takes that branch.
template <class T>
T safe_sqrt(const T& x) {
  using std::sqrt;
  if (x <= T(1e-200)) return T(0.0) * x;
  return sqrt(x);
}

}  // namespace fl::color
