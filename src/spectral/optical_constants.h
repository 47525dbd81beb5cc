#pragma once
// Optical constants n(λ), k(λ) as read from a file: blocks of tabulated data, formulas or
// constants.
#include <string>
#include <vector>

namespace fl::spectral {

// The wavelengths a computation uses: the visible grid's span (spectrum.h, 360–830 nm). A defect of
// a file outside it is a warning, not an error.
struct UsedRange {
  double min_nm = 360.0, max_nm = 830.0;
};

// One block of data. Wavelengths are stored in nm (converted once from the file's unit).
struct DispersionBlock {
  enum class Kind { TabulatedNK, TabulatedN, TabulatedK, Formula, Constant };
  Kind kind = Kind::TabulatedNK;
  int formula = 0;                   // 1..9 for Kind::Formula
  std::vector<double> coefficients;  // formula coefficients C1, C2, ...
  double min_nm = 0.0, max_nm = 0.0;
  std::vector<double> lambda_nm, n, k;  // tabulated samples
  int line = 0;                         // where the block starts in its file

  bool defines_n() const { return kind != Kind::TabulatedK; }
  bool defines_k() const {
    return kind == Kind::TabulatedNK || kind == Kind::TabulatedK || kind == Kind::Constant;
  }
};

struct OpticalConstants {
  std::string file;  // where they came from, for messages
  std::vector<DispersionBlock> blocks;
  std::vector<std::string> warnings;  // what the reader dropped or merged, one line each
  std::string reference;  // a database page's REFERENCES as plain text (empty otherwise)
};

}  // namespace fl::spectral
