#pragma once
// Optical constants n(λ), k(λ) from refractiveindex.info database files (YAML), and on a grid.
#include <optional>
#include <string>
#include <vector>

#include "spectral/optical_constants.h"
#include "spectral/spectrum.h"

namespace fl::spectral {

// refractiveindex.info formula `formula` (1..9, see the database's "Dispersion formulas") at
// lambda_um; returns n.
double evaluate_formula(int formula, const std::vector<double>& c, double lambda_um);

// Parses a refractiveindex.info YAML file. Tabulated rows are judged by `used` (tabulated.h); a
// formula is checked (physical, finite) only over the part of its range that `used` reads. Throws
// InputError naming file, line and problem.
OpticalConstants read_refractiveindex_file(const std::string& path, const UsedRange& used = {});
// A wavelength-independent index.
OpticalConstants constant_ior(double n, double k, const std::string& label);

struct SampledIor {
  ComplexIorSpectrum ior;
  std::vector<std::string> warnings;  // e.g. clamped ranges, once per quantity
  // Per grid wavelength: whether the data measures n (k) there, or holds the nearest value.
  std::vector<bool> n_measured, k_measured;
  bool has_k_data = false;  // some block defines k (otherwise k = 0 everywhere)
  std::string uncovered;  // what is held: "n and k data does not cover 360-385 nm" (empty: nothing)
};

// n and k on the grid. Outside the data's range the nearest value is used and a warning names
// the uncovered range; n data that misses the grid entirely is an InputError (k data that does is
// held at its nearest value, like any uncovered stretch). Without k data, k = 0. `label` names the
// material in messages.
SampledIor sample_ior(const OpticalConstants& oc, const SpectralGrid& grid,
                      const std::string& label);

}  // namespace fl::spectral
