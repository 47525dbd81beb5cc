#pragma once
// Tabulated optical constants as read, row by row, judged by the wavelengths the computation uses
// (docs/conventions.md, "Reading data"):
// - a row's wavelength must be a positive number, anywhere;
// - an exact duplicate of an earlier row is merged;
// - a row that repeats a wavelength with other values, or has a value that is not physical, is a
//   defect: inside the used span it is an error naming file and line; outside it the row is dropped
//   and one warning per block names the first such line;
// - a row out of order (a wavelength no other row has, listed after a longer one) is placed in
//   wavelength order inside the used span (the wavelength says where it goes; one warning per
//   block) and dropped outside it, like a defect;
// - a negative k above −kNegligibleNegativeK is read as 0.
// The used span is [UsedRange.min_nm, UsedRange.max_nm] widened to the nearest rows outside it,
// since interpolation at the range's ends reads them.
#include <string>
#include <vector>

#include "spectral/optical_constants.h"

namespace fl::spectral {

// A negative k above this is read as 0. For reflectance such a k is nothing: at n = 1.5 it changes
// F0 by k²/(n + 1)² < 4e-6 (absolute), far below anything a colour difference sees. The database's
// negatives of this size are noise around 0: −1.4e-5 on glass pages (specs/hikari/optical/LAK09 at
// 700 nm), −0.001 to −0.002 on data tabulated to three decimals (main/GaP/nk/Jellison near 500 nm).
inline constexpr double kNegligibleNegativeK = 0.005;

// Beyond any material's optical constants at any wavelength (far-infrared metals reach ~10³),
// and far below where n² + κ² would overflow in the Fresnel equations.
inline constexpr double kMaxOpticalConstant = 1e6;

// One row as read: its line, wavelength, values, and what is wrong with them (empty: nothing).
struct TabulatedRow {
  int line = 0;
  double lambda_nm = 0, n = 0, k = 0;
  std::string problem;
  bool misplaced = false;  // out of order only: its values are valid
};

class TabulatedRows {
 public:
  TabulatedRows(std::string file, DispersionBlock::Kind kind, int block_line);

  // A row with a known wavelength. For TabulatedN k is ignored, for TabulatedK n is.
  void add(int line, double lambda_nm, double n, double k);
  // A row whose wavelength is known but whose values are not (not numbers, wrong column count).
  void add_defect(int line, double lambda_nm, const std::string& problem);
  bool empty() const { return rows_.empty(); }

  // The block, after the rules above; throws InputError for a defect inside the used span or when
  // no valid row is left. Warnings are appended to `warnings`.
  DispersionBlock finish(const UsedRange& used, std::vector<std::string>& warnings) const;

 private:
  std::string file_;
  DispersionBlock::Kind kind_;
  int block_line_;
  std::vector<TabulatedRow> rows_;
};

// The physical check of one row's values: empty when n (if it has n) is in (0, kMaxOpticalConstant]
// and k (if it has k) in [0, kMaxOpticalConstant]; `k` is set to 0 when negligibly negative.
std::string value_problem(double n, double& k, bool has_n, bool has_k);

}  // namespace fl::spectral
