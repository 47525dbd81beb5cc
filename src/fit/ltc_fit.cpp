#include "fit/ltc_fit.h"

#include <ceres/ceres.h>

#include <algorithm>

namespace fl::fit {

LtcFrame ltc_frame_from_average_direction(const brdf::Vec3& average_dir) {
  const brdf::Vec3 z = brdf::normalize(brdf::Vec3{average_dir.x, 0.0, average_dir.z});
  return {{z.z, 0.0, -z.x}, {0.0, 1.0, 0.0}, z};
}

LtcMatrix ltc_matrix(const LtcFrame& f, const LtcParams& p) {
  // [X Y Z] · [[m11, 0, m13], [0, m22, 0], [0, 0, 1]]: columns m11·X, m22·Y, m13·X + Z.
  const brdf::Vec3 c0{p.m11 * f.x.x, p.m11 * f.x.y, p.m11 * f.x.z};
  const brdf::Vec3 c1{p.m22 * f.y.x, p.m22 * f.y.y, p.m22 * f.y.z};
  const brdf::Vec3 c2{p.m13 * f.x.x + f.z.x, p.m13 * f.x.y + f.z.y, p.m13 * f.x.z + f.z.z};
  return {{c0.x, c1.x, c2.x, c0.y, c1.y, c2.y, c0.z, c1.z, c2.z}};
}

LtcMatrix inverse(const LtcMatrix& a) {
  const auto& m = a.m;
  const double c00 = m[4] * m[8] - m[5] * m[7];
  const double c01 = m[5] * m[6] - m[3] * m[8];
  const double c02 = m[3] * m[7] - m[4] * m[6];
  const double inv_det = 1.0 / (m[0] * c00 + m[1] * c01 + m[2] * c02);
  return {{c00 * inv_det, (m[2] * m[7] - m[1] * m[8]) * inv_det, (m[1] * m[5] - m[2] * m[4]) * inv_det,
           c01 * inv_det, (m[0] * m[8] - m[2] * m[6]) * inv_det, (m[2] * m[3] - m[0] * m[5]) * inv_det,
           c02 * inv_det, (m[1] * m[6] - m[0] * m[7]) * inv_det, (m[0] * m[4] - m[1] * m[3]) * inv_det}};
}

LtcProblem make_ltc_problem(double nov, double alpha, double magnitude, const brdf::Vec3& average_dir,
                            int sample_sqrt) {
  LtcProblem pr;
  pr.nov = nov;
  pr.alpha = alpha;
  pr.magnitude = magnitude;
  pr.frame = ltc_frame_from_average_direction(average_dir);
  const brdf::Vec3 v = brdf::view_from_nov(nov);
  const int k = std::max(1, sample_sqrt);
  const double count = 2.0 * k * k;
  constexpr double kUniformSpherePdf = 1.0 / (4.0 * std::numbers::pi);
  auto add = [&](const brdf::Vec3& l) {
    const brdf::Vec3 sum{v.x + l.x, v.y + l.y, v.z + l.z};
    double p_vndf = 0.0;
    if (brdf::dot(sum, sum) > 0.0) {
      const brdf::Vec3 h = brdf::normalize(sum);
      if (h.z > 0.0) p_vndf = brdf::ggx_vndf_reflection_pdf(v.z, h.z, alpha);
    }
    const double q = 0.5 * p_vndf + 0.5 * kUniformSpherePdf;
    pr.samples.push_back({brdf::dot(l, pr.frame.x), brdf::dot(l, pr.frame.y), brdf::dot(l, pr.frame.z),
                          brdf::ggx_lobe_cos(v, l, alpha), 1.0 / std::sqrt(q * count)});
  };
  pr.samples.reserve(static_cast<size_t>(count));
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      const double u1 = (i + 0.5) / k, u2 = (j + 0.5) / k;
      add(brdf::reflect(v, brdf::sample_ggx_vndf(v, alpha, u1, u2)));
      const double z = 1.0 - 2.0 * u1, r = std::sqrt(std::max(0.0, 1.0 - z * z));
      const double phi = 2.0 * std::numbers::pi * u2;
      add({r * std::cos(phi), r * std::sin(phi), z});
    }
  return pr;
}

namespace {

double sum_squared_residuals(const LtcProblem& pr, const LtcParams& p) {
  double s = 0.0;
  for (const auto& smp : pr.samples) {
    const double r = (smp.target - pr.magnitude * ltc_density(p.m11, p.m22, p.m13, smp.x, smp.y, smp.z)) * smp.weight;
    s += r * r;
  }
  return s;
}

// Residual k = (ρ cos(ω_k) − n_D D_LTC(ω_k)) · w_k, so ½ Σ r² estimates ½ ∫ (ρ cos − n_D D_LTC)² dω.
struct LtcCost {
  const LtcProblem* problem;

  template <class T>
  bool operator()(const T* const p, T* residuals) const {
    const auto& samples = problem->samples;
    for (size_t k = 0; k < samples.size(); ++k) {
      const auto& s = samples[k];
      residuals[k] = (s.target - problem->magnitude * ltc_density(p[0], p[1], p[2], s.x, s.y, s.z)) * s.weight;
    }
    return true;
  }

  static ceres::CostFunction* Create(const LtcProblem& problem) {
    return new ceres::AutoDiffCostFunction<LtcCost, ceres::DYNAMIC, 3>(new LtcCost{&problem},
                                                                         static_cast<int>(problem.samples.size()));
  }
};

}  // namespace

double ltc_objective(const LtcProblem& problem, const LtcParams& p) { return 0.5 * sum_squared_residuals(problem, p); }

double ltc_fit_error(const LtcProblem& problem, const LtcParams& p) {
  double norm = 0.0;
  for (const auto& s : problem.samples) norm += (s.target * s.weight) * (s.target * s.weight);
  return norm > 0.0 ? std::sqrt(sum_squared_residuals(problem, p) / norm) : 0.0;
}

FitResult fit_ltc_ceres(const LtcProblem& problem, const LtcParams& start, bool isotropic) {
  double p[3] = {std::clamp(start.m11, kLtcMinScale, kLtcMaxScale), std::clamp(start.m22, kLtcMinScale, kLtcMaxScale),
                 std::clamp(start.m13, -kLtcMaxSkew, kLtcMaxSkew)};
  ceres::Problem pr;
  pr.AddResidualBlock(LtcCost::Create(problem), nullptr, p);
  for (int i : {0, 1}) {
    pr.SetParameterLowerBound(p, i, kLtcMinScale);
    pr.SetParameterUpperBound(p, i, kLtcMaxScale);
  }
  pr.SetParameterLowerBound(p, 2, -kLtcMaxSkew);
  pr.SetParameterUpperBound(p, 2, kLtcMaxSkew);
  if (isotropic) pr.SetManifold(p, new ceres::SubsetManifold(3, {2}));

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 200;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  options.function_tolerance = 1e-10;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-10;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &pr, &summary);

  FitResult r;
  r.parameters = {p[0], p[1], p[2]};
  r.cost = summary.final_cost;
  r.initial_cost = summary.initial_cost;
  r.iterations = static_cast<int>(summary.iterations.size());
  r.termination = ceres::TerminationTypeToString(summary.termination_type);
  r.usable = summary.IsSolutionUsable();
  r.starts = 1;
  return r;
}

}  // namespace fl::fit
