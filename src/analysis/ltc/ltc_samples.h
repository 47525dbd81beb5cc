#pragma once
// The directions an LTC cell is integrated over, shared by the held-out L3 error and the fit
// (ltc_samples.cpp, ltc_fit.cpp); internal to analysis/ltc. The lobe's own functions are declared
// in ltc_fit.h.
#include <vector>

#include "analysis/ltc/ltc_fit.h"

namespace fl::analysis {

// k² cell midpoints of the unit square, and the Hammersley set of n points.
std::vector<brdf::Point2> stratified_midpoints(int k);
std::vector<brdf::Point2> hammersley_points(int n);
// The points as disk points (for the GGX visible normals) and clamped-cosine directions.
LtcPointSet point_set(const std::vector<brdf::Point2>& pts);

// One half of a direction set at a view, as columns: the directions l, the lobe value ρ cos and the
// VNDF density at each. Columns let the compiler treat several directions per instruction; each
// direction's arithmetic is that of the scalar functions.
struct Directions {
  std::vector<double> x, y, z, target, pdf;
  explicit Directions(size_t n) : x(n), y(n), z(n), target(n), pdf(n) {}
  size_t size() const { return x.size(); }
};

// The GGX half: l = reflect(v, h) for h drawn from the visible normals at each disk point.
Directions ggx_half(const brdf::Vec3& view, double alpha, const std::vector<brdf::DiskPoint>& disk);
// The LTC half: sample_ltc_lobe at each point, from its clamped-cosine direction.
Directions ltc_half(const brdf::Vec3& view, double alpha, const LtcLobe& ltc,
                    const std::vector<brdf::Vec3>& cosine);
// The balance-heuristic L3 error over both halves of a direction set for each lobe.
std::vector<LtcL3Error> l3_errors(const brdf::Vec3& v, double alpha, double magnitude,
                                  const Directions& ggx, const LtcPointSet& set,
                                  const std::vector<LtcLobe>& lobes);
// The fitting directions of a cell: the GGX half (fixed) and the half drawn from the proposal.
LtcProblem assemble_problem(double nov, double alpha, double magnitude, const LtcFrame& frame,
                            const Directions& ggx, const LtcPointSet& set,
                            const LtcParams& proposal);

}  // namespace fl::analysis
