#include "color/colorimetry.h"

#include <fmt/format.h>

#include "util/errors.h"

namespace fl::color {

Adaptation adaptation_from_name(const std::string& name) {
  if (name == "bradford") return Adaptation::Bradford;
  if (name == "cat02") return Adaptation::Cat02;
  if (name == "none") return Adaptation::None;
  throw InputError(
      fmt::format("unknown chromatic adaptation '{}' (expected bradford, cat02 or none)", name));
}

const char* to_string(Adaptation a) {
  switch (a) {
    case Adaptation::Bradford:
      return "bradford";
    case Adaptation::Cat02:
      return "cat02";
    default:
      return "none";
  }
}

Mat3 adaptation_matrix(Adaptation method, const Xyz& src, const Xyz& dst) {
  if (method == Adaptation::None) return Mat3{};
  // Lam 1985 (Bradford) and CIE 159:2004 (CAT02) cone-response matrices.
  const Mat3 bradford{{0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296}};
  const Mat3 cat02{{0.7328, 0.4296, -0.1624, -0.7036, 1.6975, 0.0061, 0.0030, 0.0136, 0.9834}};
  const Mat3& cone = method == Adaptation::Bradford ? bradford : cat02;
  const auto s = cone.apply<double>({src.X, src.Y, src.Z});
  const auto d = cone.apply<double>({dst.X, dst.Y, dst.Z});
  return cone.inverse() * Mat3::diagonal(d[0] / s[0], d[1] / s[1], d[2] / s[2]) * cone;
}

std::vector<Xyz> xyz_weights(const spectral::Observer& obs, const spectral::Spectrum& illum) {
  const int n = illum.grid.count;
  double norm = 0;
  for (int i = 0; i < n; ++i) norm += illum.values[i] * obs.y_bar.values[i];
  std::vector<Xyz> w(n);
  for (int i = 0; i < n; ++i) {
    const double s = illum.values[i] / norm;
    w[i] = {s * obs.x_bar.values[i], s * obs.y_bar.values[i], s * obs.z_bar.values[i]};
  }
  return w;
}

}  // namespace fl::color
