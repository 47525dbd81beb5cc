// The database reader judges what the computation uses (360-830 nm): each rule on a small file
// reproducing a real page's pattern (the page is named; the database itself is never copied).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "spectral/ri_database.h"
#include "spectral/tabulated.h"
#include "spectral/text_file.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl::spectral {
namespace {

// Values written in the test files are read back exactly at their own wavelengths; between two
// rows the reader interpolates linearly, which the expected values below do by hand.
constexpr double kExact = 1e-12;

std::string nk_page(const std::string& rows) {
  return "DATA:\n  - type: tabulated nk\n    data: |\n" + rows;
}

SampledIor sample_at(const std::string& path, double lambda_nm) {
  return sample_ior(read_refractiveindex_file(path), SpectralGrid{lambda_nm, 5.0, 1}, "t");
}

// The InputError of reading and sampling `path` on the visible grid.
std::string error_of(const std::string& path, int* line = nullptr) {
  try {
    sample_ior(read_refractiveindex_file(path), SpectralGrid::visible(5.0), "t");
  } catch (const InputError& e) {
    if (line) *line = e.line();
    return e.what();
  }
  return "";
}

// main/W/nk/Weaver, main/Nb/nk/Weaver, main/Ag/nk/Yang: a row repeated exactly, far outside the
// visible. The repeat is merged and named in one warning.
TEST(ReaderRules, ExactDuplicateOutsideTheVisibleIsMerged) {
  test::TempDir tmp;
  const auto p =
      tmp.file("w.yml", nk_page("        0.07755 0.9838 1.145\n        0.07755 0.9838 1.145\n"
                                "        0.30 3.0 2.5\n        0.90 3.6 2.9\n"));
  const auto oc = read_refractiveindex_file(p);
  ASSERT_EQ(oc.blocks.front().lambda_nm.size(), 3u);
  ASSERT_EQ(oc.warnings.size(), 1u);
  EXPECT_NE(oc.warnings[0].find(p + ":5: 1 exact duplicate row merged"), std::string::npos)
      << oc.warnings[0];
}

// specs/hikari/SiO2/NIFS-U and seven more Hikari/Ohara glasses: the 370 nm row twice, inside the
// visible. Merging loses nothing: the values there are the row's own.
TEST(ReaderRules, ExactDuplicateInsideTheVisibleIsMerged) {
  test::TempDir tmp;
  const auto p =
      tmp.file("h.yml",
               "DATA:\n  - type: tabulated k\n    data: |\n        0.36 3.0e-08\n"
               "        0.37 2.9458e-08\n        0.37 2.9458e-08\n        0.90 1.0e-08\n"
               "  - type: formula 5\n    wavelength_range: 0.3 1.0\n    coefficients: 1.45\n");
  const auto s = sample_at(p, 370.0);
  EXPECT_NEAR(s.ior.ior[0].imag(), 2.9458e-08, kExact);
  EXPECT_NEAR(s.ior.ior[0].real(), 1.45, kExact);
}

// main/Ag/nk/Yang: rows out of order at 1.45-1.49 µm. Outside the used range they are dropped, with
// one warning naming the file and the first line; the visible is untouched.
TEST(ReaderRules, OutOfOrderRowsOutsideTheUsedRangeAreDroppedWithAWarning) {
  test::TempDir tmp;
  const auto p = tmp.file(
      "y.yml", nk_page("        0.30 0.20 1.0\n        0.90 0.30 6.0\n        1.46 0.23 10.25\n"
                       "        1.45 0.227 10.18\n        1.50 0.24 10.5\n"));
  const auto oc = read_refractiveindex_file(p);
  ASSERT_EQ(oc.warnings.size(), 1u);
  EXPECT_NE(oc.warnings[0].find(p + ":7: 1 row outside the used 360-830 nm dropped"),
            std::string::npos)
      << oc.warnings[0];
  EXPECT_NE(oc.warnings[0].find("1450 nm after 1460 nm"), std::string::npos) << oc.warnings[0];
  const auto s = sample_at(p, 600.0);
  EXPECT_NEAR(s.ior.ior[0].real(), 0.25, kExact);  // halfway between 300 and 900 nm
  EXPECT_NEAR(s.ior.ior[0].imag(), 3.5, kExact);
}

// specs/lzos/optical/OF1: 568.2 nm listed after 656.27 nm, inside the visible. Its wavelength says
// where it goes: it is placed in order, with a warning naming the line, and read there.
TEST(ReaderRules, OutOfOrderRowInsideTheVisibleIsPlacedInOrder) {
  test::TempDir tmp;
  const auto p = tmp.file(
      "o.yml", nk_page("        0.40 1.50 0\n        0.65627 1.52 0\n        0.5682 1.53 0\n"
                       "        0.90 1.51 0\n"));
  const auto oc = read_refractiveindex_file(p);
  ASSERT_EQ(oc.warnings.size(), 1u);
  EXPECT_NE(oc.warnings[0].find(
                p + ":6: 1 row out of order placed in wavelength order (first: wavelengths are not "
                    "strictly increasing (568.2 nm after 656.27 nm at line 5))"),
            std::string::npos)
      << oc.warnings[0];
  EXPECT_NEAR(sample_at(p, 568.2).ior.ior[0].real(), 1.53, kExact);
}

// other/mixed organic/PBDBT-ITIC/nk/Kerremans: one wavelength twice with different values, inside
// the visible: which is right cannot be told, so it is an error.
TEST(ReaderRules, RepeatedWavelengthWithOtherValuesInsideIsAnError) {
  test::TempDir tmp;
  int line = 0;
  const auto msg =
      error_of(tmp.file("k.yml", nk_page("        0.70 2.39 0.1\n        0.7126 2.38956 0.1\n"
                                         "        0.7126 2.41804 0.1\n        0.90 2.5 0.1\n")),
               &line);
  EXPECT_EQ(line, 6) << msg;
  EXPECT_NE(msg.find("712.6 nm repeats line 5 with other values"), std::string::npos) << msg;
}

// specs/crystran/optical/fused_silica-vis (k = −1.61e-9 at 1.62 µm) and specs/hikari/optical/LAK09
// (k = −1.3842e-5 at 0.7 µm, inside the visible): negligible negatives are read as 0.
TEST(ReaderRules, NegligibleNegativeKIsReadAsZero) {
  test::TempDir tmp;
  const auto p = tmp.file("f.yml", nk_page("        0.30 1.48 0\n        0.70 1.455 -1.3842e-05\n"
                                           "        1.62 1.44 -1.61e-09\n"));
  const auto oc = read_refractiveindex_file(p);
  EXPECT_TRUE(oc.warnings.empty());
  EXPECT_EQ(oc.blocks.front().k[1], 0.0);
  EXPECT_EQ(oc.blocks.front().k[2], 0.0);
  EXPECT_GT(kNegligibleNegativeK, 1.3842e-05);
  // main/GaP/nk/Jellison: k tabulated to three decimals, −0.002 at 510 nm.
  const auto g = tmp.file(
      "g.yml",
      nk_page("        0.50 3.59 -0.001\n        0.51 3.557 -0.002\n        0.90 3.2 0\n"));
  EXPECT_EQ(sample_at(g, 505.0).ior.ior[0].imag(), 0.0);
}

// other/resists/Micro resist ma-N 1407/nk/Sarkar: k = −0.013 inside the visible is not noise; the
// same value in the infrared (main/Fe2O3/nk/Querry-o, k down to −0.148 at 50 µm) is dropped.
TEST(ReaderRules, NegativeKIsAnErrorInsideAndDroppedOutside) {
  test::TempDir tmp;
  int line = 0;
  const auto msg = error_of(
      tmp.file("r.yml",
               nk_page("        0.40 1.6 0\n        0.6569 1.6 -0.01301\n        0.90 1.6 0\n")),
      &line);
  EXPECT_EQ(line, 5) << msg;
  EXPECT_NE(msg.find("k = -0.01301 is not physical"), std::string::npos) << msg;
  const auto p = tmp.file(
      "q.yml", nk_page("        0.30 2.9 0.5\n        0.90 2.6 0.01\n        50.0 3.0 -0.148\n"));
  const auto oc = read_refractiveindex_file(p);
  ASSERT_EQ(oc.warnings.size(), 1u);
  EXPECT_NE(oc.warnings[0].find("k = -0.148 is not physical"), std::string::npos) << oc.warnings[0];
}

// specs/isuzu/filter/*: n < 0 at 200-201 nm, far below the visible: dropped; the rows the
// computation reads are the same as without them.
TEST(ReaderRules, UnphysicalNFarOutsideTheVisibleIsDropped) {
  test::TempDir tmp;
  const auto p = tmp.file(
      "i.yml", nk_page("        0.200 -5.77532 1.10E-04\n        0.201 -11.04922 8.31E-05\n"
                       "        0.350 1.52 1.2E-04\n        0.900 1.50 1.0E-04\n"));
  const auto oc = read_refractiveindex_file(p);
  ASSERT_EQ(oc.warnings.size(), 1u);
  EXPECT_NE(oc.warnings[0].find(
                p + ":4: 2 rows outside the used 360-830 nm dropped (first: n = -5.77532"),
            std::string::npos)
      << oc.warnings[0];
  EXPECT_NEAR(sample_at(p, 625.0).ior.ior[0].real(), 1.51, kExact);
}

// A defect on the row that interpolation at 360 nm reads (the nearest below it) is used: an error.
TEST(ReaderRules, DefectOnTheRowBracketingTheVisibleIsAnError) {
  test::TempDir tmp;
  int line = 0;
  const auto msg = error_of(
      tmp.file("b.yml",
               nk_page("        0.20 1.5 0.1\n        0.35 -1.5 0.1\n        0.50 1.5 0.1\n"
                       "        0.90 1.5 0.1\n")),
      &line);
  EXPECT_EQ(line, 5) << msg;
}

// main/CS2/nk/Chemnitz: formula 1 over 0.3-12 µm, NaN at 6.5 µm (a pole of its second term) and
// fine in the visible. It is checked only where it is read; n at 500 nm is the formula's own value,
// written out here: n² = 1 + 1.499426 λ²/(λ² − 0.178763²) + 0.089531 λ²/(λ² − 6.591946²).
TEST(ReaderRules, FormulaIsCheckedOnlyWhereItIsRead) {
  test::TempDir tmp;
  const auto p = tmp.file("c.yml",
                          "DATA:\n  - type: formula 1\n    wavelength_range: 0.3 12\n"
                          "    coefficients: 0 1.499426 0.178763 0.089531 6.591946\n");
  const double l2 = 0.25;
  const double n = std::sqrt(1 + 1.499426 * l2 / (l2 - 0.178763 * 0.178763) +
                             0.089531 * l2 / (l2 - 6.591946 * 6.591946));
  EXPECT_NEAR(sample_at(p, 500.0).ior.ior[0].real(), n, kExact);
  // A pole inside the visible (C3 = 0.6 µm) is an error: n² < 0 from 0.6/√2.5 = 0.3795 µm up to the
  // pole, so the first nm it fails at is 380.
  int line = 0;
  const auto msg = error_of(tmp.file("d.yml",
                                     "DATA:\n  - type: formula 1\n    wavelength_range: 0.3 12\n"
                                     "    coefficients: 0 1.5 0.6\n"),
                            &line);
  EXPECT_NE(msg.find("formula 1 gives n = nan at 0.38 um (not physical)"), std::string::npos)
      << msg;
  EXPECT_EQ(line, 4);
}

// main/Al2O3/nk/Franta, main/SiO2/nk/Franta: k = 5.0434142077e-317, a denormal (strtod reports
// underflow with ERANGE). It is a number; overflow is not.
TEST(ReaderRules, DenormalsAreNumbers) {
  double v = -1;
  ASSERT_TRUE(parse_finite("5.0434142077e-317", v));
  EXPECT_EQ(v, 5.0434142077e-317);
  EXPECT_GT(v, 0.0);
  EXPECT_TRUE(parse_finite("1e-400", v));  // rounds to 0
  EXPECT_EQ(v, 0.0);
  EXPECT_FALSE(parse_finite("1e400", v));
  test::TempDir tmp;
  const auto p =
      tmp.file("a.yml", nk_page("        0.30 1.79 5.0434142077e-317\n        0.90 1.76 1e-310\n"));
  EXPECT_NEAR(sample_at(p, 600.0).ior.ior[0].real(), 1.775, kExact);
}

// Decimal numbers are read correctly rounded (against the compiler's reading of the same literals,
// hard cases included), with an optional sign; anything else in the field is not a number.
TEST(ReaderRules, NumbersAreDecimalCorrectlyRoundedAndSigned) {
  double v = 0;
  const std::pair<const char*, double> numbers[] = {
      {"0.1", 0.1},
      {"+1.5", 1.5},
      {"-.5", -0.5},
      {"5.", 5.0},
      {" 2.5e3\t", 2.5e3},
      {"2.2250738585072011e-308", 2.2250738585072011e-308},
      {"1.7976931348623157e308", 1.7976931348623157e308},
      {"9007199254740993", 9007199254740993.0},
      {"0.30000000000000004", 0.30000000000000004}};
  for (const auto& [text, expected] : numbers) {
    ASSERT_TRUE(parse_finite(text, v)) << text;
    EXPECT_EQ(v, expected) << text;
  }
  EXPECT_TRUE(parse_finite("-1e-400", v));
  EXPECT_EQ(v, 0.0);
  EXPECT_TRUE(std::signbit(v));
  for (const char* text : {"", "+", "-", "1,5", "1.5e", "0x10", "nan", "inf", "-inf", "+-1", "1 2",
                           "1.7976931348623159e308", "e5"})
    EXPECT_FALSE(parse_finite(text, v)) << text;
}

}  // namespace
}  // namespace fl::spectral
