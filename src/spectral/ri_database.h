#pragma once
// Optical constants n(λ), k(λ) from refractiveindex.info database files (YAML) and plain CSV.
#include <optional>
#include <string>
#include <vector>

#include "spectral/spectrum.h"

namespace fl::spectral {

// One DATA block of a refractiveindex.info file. Wavelengths are stored in nm (converted once
// from the file's µm).
struct DispersionBlock {
  enum class Kind { TabulatedNK, TabulatedN, TabulatedK, Formula, Constant };
  Kind kind = Kind::TabulatedNK;
  int formula = 0;                  // 1..9 for Kind::Formula
  std::vector<double> coefficients; // formula coefficients C1, C2, ...
  double min_nm = 0.0, max_nm = 0.0;
  std::vector<double> lambda_nm, n, k;  // tabulated samples
  int line = 0;                         // where the block starts in its file

  bool defines_n() const { return kind != Kind::TabulatedK; }
  bool defines_k() const { return kind == Kind::TabulatedNK || kind == Kind::TabulatedK || kind == Kind::Constant; }
};

struct OpticalConstants {
  std::string file;  // where they came from, for messages
  std::vector<DispersionBlock> blocks;
};

// refractiveindex.info formula `formula` (1..9, see the database's "Dispersion formulas") at
// lambda_um; returns n.
double evaluate_formula(int formula, const std::vector<double>& c, double lambda_um);

// Parses a refractiveindex.info YAML file. Throws InputError naming file, line and problem.
OpticalConstants read_refractiveindex_file(const std::string& path);
// Parses CSV with header `lambda_nm,n,k` (k may be omitted: `lambda_nm,n`).
OpticalConstants read_nk_csv(const std::string& path);
// A wavelength-independent index.
OpticalConstants constant_ior(double n, double k, const std::string& label);

struct SampledIor {
  ComplexIorSpectrum ior;
  std::vector<std::string> warnings;  // e.g. clamped ranges, once per quantity
};

// n and k on the grid. Outside the data's range the nearest value is used and a warning names
// the uncovered range; a range that misses the grid entirely is an InputError. Without k data,
// k = 0. `label` names the material in messages.
SampledIor sample_ior(const OpticalConstants& oc, const SpectralGrid& grid, const std::string& label);

}  // namespace fl::spectral
