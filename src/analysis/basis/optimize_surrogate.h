#pragma once
// A smooth surrogate of the projection metric, for optimize.cpp. Per page and angle j,
// ΔE2000² ≈ |J_j r_j|² = r_jᵀ G_j r_j: J_j the derivative over RGB of the three CIEDE2000 residuals
// at the truth (color::ciede2000_residuals_batch), r_j the RGB residual of the per-channel
// least-squares projection on the basis. A page's squared error is s = mean_j r_jᵀ G_j r_j, its
// error e = √s. At the SVD basis the surrogate is within 0.003 of the exact RMS ΔE2000.
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "analysis/basis/optimize.h"

namespace fl::analysis {

struct SurrogatePage {
  bool metal = false;
  Eigen::MatrixXd truth;                    // angles × 3, linear RGB
  std::vector<std::array<double, 6>> gram;  // per angle G = JᵀJ: 00 01 02 11 12 22
};

// Each page's truth and G at the context's angles.
std::vector<SurrogatePage> surrogate_pages(const Context& ctx,
                                           const std::vector<const LoadedMaterial*>& pages);

class Surrogate {
 public:
  Surrogate(const std::vector<SurrogatePage>& pages, BasisObjective objective);
  // The objective for the basis b (angles × K, its last `free` columns the free functions), and
  // with `gradient` its gradient over those columns' samples (angles × free).
  double value(const Eigen::MatrixXd& b, int free, Eigen::MatrixXd* gradient) const;
  // Each page's surrogate error e.
  std::vector<double> errors(const Eigen::MatrixXd& b) const;

 private:
  struct PageEval {
    double s = 0;           // squared error
    Eigen::MatrixXd ds_db;  // angles × free
  };
  PageEval evaluate(const SurrogatePage& page, const Eigen::MatrixXd& b,
                    const Eigen::MatrixXd& minv, int free) const;
  // ∂objective/∂s_p per page, and the objective.
  double weigh(const std::vector<double>& s, std::vector<double>& d) const;

  const std::vector<SurrogatePage>& pages_;
  BasisObjective objective_;
  std::vector<size_t> metals_, others_;
};

}  // namespace fl::analysis
