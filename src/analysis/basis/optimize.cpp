// The free functions chosen by L-BFGS (Ceres' gradient solver) on the surrogate of
// optimize_surrogate.h, each a polynomial of the construction's degree, orthogonal to b0 = 1.
#include "analysis/basis/optimize.h"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

#include "analysis/basis/basis.h"
#include "analysis/basis/optimize_surrogate.h"

namespace fl::analysis {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// The iterations an L-BFGS run may take: the K = 4 stage converges (relative change of the
// objective below 1e-12) after about 950 from the SVD's functions, the others within 20.
constexpr int kIterations = 2000;

// An orthonormal basis (under the plain sum over the samples) of the polynomials of degree
// ≤ `degree` in x = 2μ − 1 that are orthogonal to `fixed`: sampled (samples × m) and as
// coefficients (degree + 1 × m).
struct FreeSpace {
  MatrixXd sampled, coeffs;
};

// Householder QR one column at a time (Eigen's HouseholderQR blocks only from 48 columns; these
// have at most 17), so the same sums on every CPU.
MatrixXd orthonormal_columns(const MatrixXd& a) {
  Eigen::HouseholderQR<MatrixXd> qr(a);
  return qr.householderQ() * MatrixXd::Identity(a.rows(), a.cols());
}

FreeSpace free_space(const std::vector<double>& mu, const MatrixXd& fixed, int degree) {
  const Eigen::Index n = static_cast<Eigen::Index>(mu.size());
  MatrixXd v(n, degree + 1);
  for (Eigen::Index j = 0; j < n; ++j) {
    double p = 1;
    for (int i = 0; i <= degree; ++i, p *= 2 * mu[static_cast<size_t>(j)] - 1) v(j, i) = p;
  }
  Eigen::HouseholderQR<MatrixXd> qr(v);
  const MatrixXd qv = qr.householderQ() * MatrixXd::Identity(n, degree + 1);
  const MatrixXd rv = qr.matrixQR().topRows(degree + 1).triangularView<Eigen::Upper>();
  const MatrixXd in_qv = qv.transpose().lazyProduct(fixed);
  Eigen::HouseholderQR<MatrixXd> qf(in_qv);
  const MatrixXd full = qf.householderQ() * MatrixXd::Identity(degree + 1, degree + 1);
  const MatrixXd z = full.rightCols(degree + 1 - fixed.cols());
  return {qv.lazyProduct(z), rv.triangularView<Eigen::Upper>().solve(z)};
}

// The objective over the coordinates x (space.cols() × free, column-major) of the free functions
// in the free space: the basis [fixed, space·x].
class Objective : public ceres::FirstOrderFunction {
 public:
  Objective(const Surrogate& s, const MatrixXd& fixed, const MatrixXd& space, int free)
      : s_(s), fixed_(fixed), space_(space), free_(free) {}
  int NumParameters() const override { return static_cast<int>(space_.cols()) * free_; }
  bool Evaluate(const double* x, double* cost, double* gradient) const override {
    const Eigen::Index m = space_.cols();
    MatrixXd b(fixed_.rows(), fixed_.cols() + free_);
    b.leftCols(fixed_.cols()) = fixed_;
    b.rightCols(free_) = space_.lazyProduct(Eigen::Map<const MatrixXd>(x, m, free_));
    MatrixXd grad;
    *cost = s_.value(b, free_, gradient ? &grad : nullptr);
    if (gradient) Eigen::Map<MatrixXd>(gradient, m, free_) = space_.transpose().lazyProduct(grad);
    return true;
  }

 private:
  const Surrogate& s_;
  const MatrixXd& fixed_;
  const MatrixXd& space_;
  int free_;
};

// The coordinates (space.cols() × x0.cols()) that minimize the objective from x0, orthonormal.
MatrixXd solve(const Surrogate& s, const MatrixXd& fixed, const MatrixXd& space, MatrixXd x,
               int rounds, const std::function<void()>& round_done) {
  const int free = static_cast<int>(x.cols());
  for (int round = 0; round < rounds; ++round) {
    x = orthonormal_columns(x);
    ceres::GradientProblemSolver::Options options;
    options.max_num_iterations = kIterations;
    options.function_tolerance = 1e-12;
    options.gradient_tolerance = 1e-14;
    options.parameter_tolerance = 1e-14;
    options.logging_type = ceres::SILENT;
    ceres::GradientProblemSolver::Summary summary;
    ceres::GradientProblem problem(new Objective(s, fixed, space, free));
    ceres::Solve(options, problem, x.data(), &summary);
    if (!summary.IsSolutionUsable())
      throw std::runtime_error("basis: L-BFGS failed: " + summary.message);
    if (round_done) round_done();
  }
  return orthonormal_columns(x);
}

// A sampled function as a column.
MatrixXd as_column(const std::vector<double>& f) {
  return Eigen::Map<const MatrixXd>(f.data(), static_cast<Eigen::Index>(f.size()), 1);
}

std::vector<double> column(const MatrixXd& m, Eigen::Index c) {
  return {m.col(c).data(), m.col(c).data() + m.rows()};
}

}  // namespace

std::vector<std::vector<double>> optimize_terms(const Context& ctx,
                                                const std::vector<const LoadedMaterial*>& pages,
                                                const std::vector<std::vector<double>>& initial,
                                                int degree,
                                                const std::function<void()>& round_done) {
  const auto& mu = ctx.cos_thetas();
  const auto data = surrogate_pages(ctx, pages);
  const Surrogate surrogate(data, BasisObjective{});
  const Surrogate nested(data, nested_objective());
  const auto fixed = basis_fixed_span(mu);
  const MatrixXd one = as_column(fixed[0]);
  const FreeSpace fs = free_space(mu, one, degree);

  // K = 4: span{b1, b2, b3} from {(1 − μ)⁵, b2, b3}.
  MatrixXd start(one.rows(), 3);
  start.col(0) = as_column(fixed[1]);
  for (Eigen::Index k = 1; k < 3; ++k)
    for (Eigen::Index j = 0; j < start.rows(); ++j)
      start(j, k) = initial[static_cast<size_t>(k - 1)][static_cast<size_t>(j)];
  const MatrixXd x = solve(surrogate, one, fs.sampled, fs.sampled.transpose().lazyProduct(start),
                           kOptimizeRounds, round_done);
  MatrixXd span = fs.sampled.lazyProduct(x), coeffs = fs.coeffs.lazyProduct(x);

  // K = 3, then 2: within the span, the m-dimensional subspace best on the nested objective, so
  // that every K's functions are the first K's of the next.
  for (Eigen::Index m = 2; m >= 1; --m) {
    const MatrixXd q = span.leftCols(m + 1);
    const MatrixXd y =
        solve(nested, one, q, MatrixXd::Identity(m + 1, m), kNestedRounds, round_done);
    // Q of y's QR: its first m columns span y's, the last completes the span.
    Eigen::HouseholderQR<MatrixXd> qr(y);
    const MatrixXd rotation = qr.householderQ() * MatrixXd::Identity(m + 1, m + 1);
    span.leftCols(m + 1) = q.lazyProduct(rotation);
    coeffs.leftCols(m + 1) = MatrixXd(coeffs.leftCols(m + 1)).lazyProduct(rotation);
  }
  std::vector<std::vector<double>> out;
  for (Eigen::Index f = 0; f < coeffs.cols(); ++f) out.push_back(column(coeffs, f));

  // K = 5: b4 with the others fixed, from the SVD's b4.
  MatrixXd fixed4(one.rows(), 4);
  fixed4 << one, span;
  const FreeSpace f4 = free_space(mu, fixed4, degree);
  MatrixXd b4(one.rows(), 1);
  for (Eigen::Index j = 0; j < b4.rows(); ++j) b4(j, 0) = initial[2][static_cast<size_t>(j)];
  const MatrixXd y = solve(surrogate, fixed4, f4.sampled, f4.sampled.transpose().lazyProduct(b4),
                           kOptimizeRounds, round_done);
  out.push_back(column(f4.coeffs.lazyProduct(y), 0));
  return out;
}

}  // namespace fl::analysis
