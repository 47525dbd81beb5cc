#include "analysis/basis/basis.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "util/errors.h"

namespace fl::analysis {

std::vector<double> basis_mu_samples(int m) {
  std::vector<double> mu(m);
  for (int j = 0; j < m; ++j) {
    const double theta = (std::numbers::pi / 2) * j / (m - 1);
    mu[j] = j == m - 1 ? 0.0 : std::cos(theta);
  }
  return mu;
}

const char* basis_weighting_name(BasisWeighting w) {
  switch (w) {
    case BasisWeighting::Pages:
      return "pages";
    case BasisWeighting::Classes:
      return "classes";
    case BasisWeighting::Perceptual:
      return "perceptual";
  }
  return "?";
}

BasisWeighting basis_weighting_from_name(const std::string& name) {
  for (const auto w : {BasisWeighting::Pages, BasisWeighting::Classes, BasisWeighting::Perceptual})
    if (name == basis_weighting_name(w)) return w;
  throw InputError("basis: --weighting '" + name + "': expected pages, classes or perceptual");
}

const char* basis_construction_name(BasisConstruction c) {
  return c == BasisConstruction::Svd ? "svd" : "optimized";
}

BasisConstruction basis_construction_from_name(const std::string& name) {
  for (const auto c : {BasisConstruction::Svd, BasisConstruction::Optimized})
    if (name == basis_construction_name(c)) return c;
  throw InputError("basis: --construction '" + name + "': expected svd or optimized");
}

double basis_fixed_term(int k, double mu) {
  const double s = 1.0 - mu;
  return k == 0 ? 1.0 : s * s * s * s * s;
}

std::vector<std::vector<double>> basis_fixed_span(const std::vector<double>& mu) {
  std::vector<std::vector<double>> span(2, std::vector<double>(mu.size()));
  for (size_t j = 0; j < mu.size(); ++j)
    for (int k = 0; k < 2; ++k) span[k][j] = basis_fixed_term(k, mu[j]);
  return span;
}

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

MatrixXd sampled_matrix(const std::vector<std::vector<double>>& functions) {
  MatrixXd b(functions.front().size(), functions.size());
  for (size_t k = 0; k < functions.size(); ++k)
    for (size_t j = 0; j < functions[k].size(); ++j) b(j, k) = functions[k][j];
  return b;
}

// The upper triangle of the QR factor of `a` (its first `cols` rows; zero rows when shorter), by
// Householder reflections one column at a time. Eigen's HouseholderQR applies its reflections in
// blocks, as matrix products whose blocking it sizes from the CPU's cache sizes (read with cpuid),
// so its sums run in another order, and round differently, on a CPU with other caches; a
// reflection applied to the remaining columns is a matrix-vector product, summed in the same order
// on every CPU.
MatrixXd triangular_factor(MatrixXd a) {
  const Eigen::Index n = a.cols(), k = std::min(a.rows(), n);
  VectorXd workspace(n);
  for (Eigen::Index j = 0; j < k; ++j) {
    const Eigen::Index below = a.rows() - j;
    double tau = 0, beta = 0;
    a.col(j).tail(below).makeHouseholderInPlace(tau, beta);
    a(j, j) = beta;
    a.bottomRightCorner(below, n - j - 1)
        .applyHouseholderOnTheLeft(a.col(j).tail(below - 1), tau, workspace.data());
  }
  MatrixXd r = MatrixXd::Zero(n, n);
  r.topRows(k) = a.topRows(k).triangularView<Eigen::Upper>();
  return r;
}

}  // namespace

struct ResidualStack::Impl {
  MatrixXd fixed_q;  // orthonormal basis of span{1, (1 − μ)⁵} at the samples
  MatrixXd r;        // the stack's triangular factor
  double total_energy = 0, residual_energy = 0;
};

ResidualStack::ResidualStack(const std::vector<double>& mu) : impl_(std::make_unique<Impl>()) {
  Eigen::HouseholderQR<MatrixXd> qr(sampled_matrix(basis_fixed_span(mu)));
  impl_->fixed_q = qr.householderQ() * MatrixXd::Identity(mu.size(), 2);
  impl_->r = MatrixXd::Zero(mu.size(), mu.size());
}

ResidualStack::~ResidualStack() = default;

void ResidualStack::add(const CurveRows& rows) {
  const int m = static_cast<int>(impl_->r.cols());
  MatrixXd stack(m + rows.rows(), m);
  stack.topRows(m) = impl_->r;
  for (int i = 0; i < rows.rows(); ++i) {
    const VectorXd f = Eigen::Map<const VectorXd>(rows.values.data() + size_t(i) * m, m);
    const VectorXd res = f - impl_->fixed_q * (impl_->fixed_q.transpose() * f);
    const double w = rows.weights[i];
    impl_->total_energy += w * f.squaredNorm();
    impl_->residual_energy += w * res.squaredNorm();
    stack.row(m + i) = std::sqrt(w) * res.transpose();
  }
  impl_->r = triangular_factor(std::move(stack));
}

void ResidualStack::merge(const ResidualStack& other) {
  const Eigen::Index m = impl_->r.cols();
  MatrixXd stack(2 * m, m);
  stack << impl_->r, other.impl_->r;
  impl_->r = triangular_factor(std::move(stack));
  impl_->total_energy += other.impl_->total_energy;
  impl_->residual_energy += other.impl_->residual_energy;
}

ResidualSvd ResidualStack::solve(int terms) const {
  Eigen::JacobiSVD<MatrixXd> svd(impl_->r, Eigen::ComputeFullV);
  ResidualSvd out;
  out.total_energy = impl_->total_energy;
  out.residual_energy = impl_->residual_energy;
  const VectorXd& s = svd.singularValues();
  out.singular_values.assign(s.data(), s.data() + s.size());
  for (int k = 0; k < terms; ++k) {
    VectorXd v = svd.matrixV().col(k);
    Eigen::Index at = 0;
    for (Eigen::Index j = 1; j < v.size(); ++j)
      if (std::abs(v(j)) > std::abs(v(at))) at = j;
    if (v(at) < 0) v = -v;
    out.functions.emplace_back(v.data(), v.data() + v.size());
  }
  return out;
}

std::vector<double> fit_polynomial(const std::vector<double>& x, const std::vector<double>& f,
                                   int degree) {
  MatrixXd v(x.size(), degree + 1);
  for (size_t j = 0; j < x.size(); ++j) {
    double p = 1.0;
    for (int i = 0; i <= degree; ++i, p *= x[j]) v(j, i) = p;
  }
  const VectorXd c = v.colPivHouseholderQr().solve(Eigen::Map<const VectorXd>(f.data(), f.size()));
  return {c.data(), c.data() + c.size()};
}

double eval_polynomial(const std::vector<double>& c, double x) {
  double p = 0.0;
  for (size_t i = c.size(); i-- > 0;) p = p * x + c[i];
  return p;
}

// Σ_i c_i (2μ − 1)^i = Σ_i c_i Σ_j C(i, j) 2^j μ^j (−1)^(i−j).
std::vector<double> centred_to_mu(const std::vector<double>& c) {
  const size_t n = c.size();
  std::vector<double> out(n, 0.0);
  std::vector<double> row = {1.0};  // binomial coefficients C(i, j)
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j <= i; ++j)
      out[j] += c[i] * row[j] * std::ldexp(1.0, static_cast<int>(j)) * ((i - j) % 2 ? -1.0 : 1.0);
    std::vector<double> next(i + 2, 1.0);
    for (size_t j = 1; j <= i; ++j) next[j] = row[j - 1] + row[j];
    row = next;
  }
  return out;
}

Projector::Projector(const std::vector<std::vector<double>>& basis) : basis_(basis) {
  const MatrixXd b = sampled_matrix(basis);
  const MatrixXd pinv = b.colPivHouseholderQr().solve(MatrixXd::Identity(b.rows(), b.rows()));
  pinv_.resize(pinv.size());
  // Row-major: coefficient k is the dot product of row k with f.
  for (Eigen::Index k = 0; k < pinv.rows(); ++k)
    for (Eigen::Index j = 0; j < pinv.cols(); ++j) pinv_[k * pinv.cols() + j] = pinv(k, j);
}

std::vector<double> Projector::coefficients(const std::vector<double>& f) const {
  std::vector<double> c(basis_.size(), 0.0);
  for (size_t k = 0; k < c.size(); ++k)
    for (size_t j = 0; j < f.size(); ++j) c[k] += pinv_[k * f.size() + j] * f[j];
  return c;
}

std::vector<double> Projector::residual(const std::vector<double>& f) const {
  const auto c = coefficients(f);
  std::vector<double> r = f;
  for (size_t k = 0; k < c.size(); ++k)
    for (size_t j = 0; j < f.size(); ++j) r[j] -= c[k] * basis_[k][j];
  return r;
}

}  // namespace fl::analysis
