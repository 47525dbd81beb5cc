// Belcour, Bati & Barla 2020, "Bringing an accurate Fresnel to real-time rendering: a
// preintegrable decomposition" (SIGGRAPH 2020 talk and Physically Based Shading course,
// supplemental notebook): their basis rebuilt from the construction they describe, as a peer.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>

#include "analysis/basis/basis.h"
#include "fresnel/exact.h"
#include "util/parallel.h"

namespace fl::analysis {

namespace {

using Eigen::MatrixXd;

// Gulbrandsen 2014 ("Artist friendly metallic Fresnel") at edge tint g = 1: η = (1 − r)/(1 + r),
// κ² = (r(1 + η)² − (η − 1)²)/(1 − r).
std::complex<double> conductor_of_reflectivity(double r) {
  const double eta = (1 - r) / (1 + r);
  const double kappa2 = (r * (1 + eta) * (1 + eta) - (eta - 1) * (eta - 1)) / (1 - r);
  return {eta, std::sqrt(std::max(0.0, kappa2))};
}

// The curves' indices: η = 1.1 first, then kBelcourConductors conductors, then dielectrics with η
// uniform from 1.01 to 3 (the last at 1.01 + 1.99·(N − 1 − c)/(N − c) for c conductors).
std::vector<std::complex<double>> belcour_indices() {
  std::vector<std::complex<double>> out = {{1.1, 0.0}};
  const int n = kBelcourCurves, c = kBelcourConductors;
  for (int k = 1; k <= c; ++k)
    out.push_back(conductor_of_reflectivity(std::min(double(k) / c, kBelcourMaxReflectivity)));
  for (int k = c + 1; k < n; ++k) {
    const double r = (double(k) / n - double(c) / n) / (1.0 - double(c) / n);
    out.push_back({1.01 + (3.0 - 1.01) * r, 0.0});
  }
  return out;
}

// The leading `count` right singular vectors of the rows (curves × samples): eigenvectors of the
// Gram matrix Σ_c f_c f_cᵀ, summed curve by curve in order (the same sums on every CPU), largest
// eigenvalue first, each with its largest-magnitude sample positive.
std::vector<std::vector<double>> leading_vectors(const std::vector<std::vector<double>>& rows,
                                                 int count) {
  const size_t m = rows.front().size();
  MatrixXd gram(m, m);
  parallel_for(m, [&](size_t i) {
    for (size_t j = 0; j <= i; ++j) {
      double sum = 0;
      for (const auto& f : rows) sum += f[i] * f[j];
      gram(i, j) = gram(j, i) = sum;
    }
  });
  const Eigen::SelfAdjointEigenSolver<MatrixXd> eig(gram);
  std::vector<std::vector<double>> out;
  for (int k = 0; k < count; ++k) {
    Eigen::VectorXd v = eig.eigenvectors().col(static_cast<Eigen::Index>(m) - 1 - k);
    Eigen::Index at = 0;
    v.cwiseAbs().maxCoeff(&at);
    if (v(at) < 0) v = -v;
    out.emplace_back(v.data(), v.data() + v.size());
  }
  return out;
}

std::vector<double> scaled_to_unit_peak(std::vector<double> v) {
  double peak = 0;
  for (double x : v) peak = std::max(peak, std::abs(x));
  for (double& x : v) x /= peak;
  return v;
}

}  // namespace

PeerBasis belcour_basis(int data_terms) {
  PeerBasis b;
  for (int j = 0; j < kBelcourSamples; ++j) b.mu.push_back(double(j) / (kBelcourSamples - 1));
  std::vector<std::vector<double>> curves;
  for (const auto& eta : belcour_indices()) {
    const double f0 = fresnel::fresnel_conductor(1.0, eta);
    std::vector<double> f;
    for (double m : b.mu) f.push_back((fresnel::fresnel_conductor(m, eta) - f0) / (1 - f0));
    curves.push_back(std::move(f));
  }
  std::vector<double> b1 = leading_vectors(curves, 1).front();
  for (double& x : b1) x = std::abs(x);
  b1 = scaled_to_unit_peak(std::move(b1));
  for (auto& f : curves)
    for (size_t j = 0; j < f.size(); ++j) f[j] -= b1[j];
  b.functions = {std::vector<double>(b.mu.size(), 1.0), b1};
  for (auto& v : leading_vectors(curves, data_terms))
    b.functions.push_back(scaled_to_unit_peak(std::move(v)));
  // Their two angles: b2's maximum, and whichever of b3's maximum and minimum lies farther from it.
  const auto& b2 = b.functions[2];
  const auto& b3 = b.functions[3];
  const auto i1 = static_cast<size_t>(std::max_element(b2.begin(), b2.end()) - b2.begin());
  const auto hi = static_cast<size_t>(std::max_element(b3.begin(), b3.end()) - b3.begin());
  const auto lo = static_cast<size_t>(std::min_element(b3.begin(), b3.end()) - b3.begin());
  const auto gap = [&](size_t i) { return i > i1 ? i - i1 : i1 - i; };
  b.two_point = {i1, gap(hi) > gap(lo) ? hi : lo};
  return b;
}

double PeerBasis::operator()(size_t k, double mu) const {
  const double at = std::clamp(mu, 0.0, 1.0) * double(this->mu.size() - 1);
  const auto j = std::min(static_cast<size_t>(at), this->mu.size() - 2);
  const double t = at - double(j);
  return (1 - t) * functions[k][j] + t * functions[k][j + 1];
}

std::array<double, 4> PeerBasis::two_point_coefficients(double f_at_1, double f_at_a,
                                                        double f_at_b) const {
  std::array<double, 4> c{};
  c[0] = f_at_1;
  c[1] = 1.0 - f_at_1;
  const size_t a = two_point[0], b = two_point[1];
  const double ra = f_at_a - (c[0] + c[1] * functions[1][a]);
  const double rb = f_at_b - (c[0] + c[1] * functions[1][b]);
  // [ra rb] = [c2 c3]·[[b2(a) b2(b)], [b3(a) b3(b)]]
  const double m00 = functions[2][a], m01 = functions[2][b];
  const double m10 = functions[3][a], m11 = functions[3][b];
  const double det = m00 * m11 - m01 * m10;
  c[2] = (ra * m11 - rb * m10) / det;
  c[3] = (rb * m00 - ra * m01) / det;
  return c;
}

}  // namespace fl::analysis
