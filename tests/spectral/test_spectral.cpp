// Database reader, interpolation, catalog.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "spectral/material.h"
#include "spectral/nk_text.h"
#include "spectral/ri_database.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl::spectral {
namespace {

// Hand-computed (Python, double precision) refractive indices at 0.5 µm for the synthetic
// coefficients below; the formulas are those of the database's "Dispersion formulas".
constexpr double kFormulaTolerance = 1e-12;

struct FormulaCase {
  int formula;
  const char* coefficients;
  double expected_n_at_500nm;
};

class FormulaTest : public ::testing::TestWithParam<FormulaCase> {};

TEST_P(FormulaTest, MatchesHandComputedValue) {
  const auto& c = GetParam();
  test::TempDir tmp;
  const std::string path = tmp.file(
      "f.yml", std::string("DATA:\n  - type: formula ") + std::to_string(c.formula) +
                   "\n    wavelength_range: 0.3 1.0\n    coefficients: " + c.coefficients + "\n");
  const auto oc = read_refractiveindex_file(path);
  ASSERT_EQ(oc.blocks.size(), 1u);
  EXPECT_NEAR(oc.blocks[0].min_nm, 300.0, 1e-9);
  EXPECT_NEAR(oc.blocks[0].max_nm, 1000.0, 1e-9);
  const auto s = sample_ior(oc, SpectralGrid{500.0, 5.0, 1}, "test");
  EXPECT_NEAR(s.ior.ior[0].real(), c.expected_n_at_500nm, kFormulaTolerance);
  EXPECT_EQ(s.ior.ior[0].imag(), 0.0);
}

// n² − 1 = 0.1 + 1.0·λ²/(λ² − 0.1²) + 0.5·λ²/(λ² − 10²) etc.
INSTANTIATE_TEST_SUITE_P(
    AllFormulaTypes, FormulaTest,
    ::testing::Values(FormulaCase{1, "0.1 1.0 0.1 0.5 10", 1.4630152199599928},
                      FormulaCase{2, "0.1 1.0 0.01 0.5 100", 1.4630152199599928},
                      FormulaCase{3, "2.0 0.01 2 0.02 -2", 1.4430869689661812},
                      FormulaCase{4, "2.0 0.5 2 0.1 2 0 0 0 0 0.01 2", 1.588500340992514},
                      FormulaCase{5, "1.5 0.004 -2", 1.516},
                      FormulaCase{6, "0.0001 0.01 100", 1.0002041666666666},
                      FormulaCase{7, "1.5 0.01 0.001 0.002", 1.5658356058761465},
                      FormulaCase{8, "0.3 0.01 0.01 0.001", 1.5336332507400943},
                      FormulaCase{9, "2.0 0.01 0.01 0.001 0.3 0.01", 1.4302680401472538}),
    [](const ::testing::TestParamInfo<FormulaCase>& info) {
      return "formula" + std::to_string(info.param.formula);
    });

TEST(Database, MissingTrailingCoefficientsAreZero) {
  // The database's own main/AgGaSe2/nk/Boyd-o is formula 2 with C1 and one and a half pairs.
  test::TempDir tmp;
  const auto short_form = tmp.file("s.yml",
                                   "DATA:\n  - type: formula 2\n    wavelength_range: 0.3 1.0\n    "
                                   "coefficients: 0.1 1.0 0.01 0.5\n");
  const auto padded = tmp.file("p.yml",
                               "DATA:\n  - type: formula 2\n    wavelength_range: 0.3 1.0\n    "
                               "coefficients: 0.1 1.0 0.01 0.5 0\n");
  const SpectralGrid g{500.0, 5.0, 1};
  EXPECT_EQ(sample_ior(read_refractiveindex_file(short_form), g, "s").ior.ior[0],
            sample_ior(read_refractiveindex_file(padded), g, "p").ior.ior[0]);
}

constexpr double kSchottNdTolerance = 2e-5;  // the catalog's nd is printed to 5 decimals

TEST(Database, SchottGlassFormulaPlusTabulatedK) {
  // SF66: n from formula 2, k tabulated; nd (587.56 nm) is printed in the file's PROPERTIES.
  const auto oc =
      read_refractiveindex_file(std::string(FL_DEFAULT_DB) + "/data/specs/schott/optical/SF66.yml");
  ASSERT_EQ(oc.blocks.size(), 2u);
  EXPECT_EQ(oc.blocks[0].kind, DispersionBlock::Kind::Formula);
  EXPECT_EQ(oc.blocks[1].kind, DispersionBlock::Kind::TabulatedK);
  const auto s = sample_ior(oc, SpectralGrid{587.56, 1.0, 1}, "SF66");
  EXPECT_NEAR(s.ior.ior[0].real(), 1.92286, kSchottNdTolerance);
  // k between the tabulated 0.580 µm (2.2288e-8) and 0.620 µm (2.1829e-8) points.
  EXPECT_NEAR(s.ior.ior[0].imag(), 2.2288e-8 + (587.56 - 580.0) / 40.0 * (2.1829e-8 - 2.2288e-8),
              1e-15);
}

TEST(Database, TabulatedNkInterpolatesLinearlyAndWarnsOnce) {
  test::TempDir tmp;
  const auto path = tmp.file(
      "t.yml",
      "DATA:\n  - type: tabulated nk\n    data: |\n        0.40 1.0 2.0\n        0.60 2.0 4.0\n");
  const auto s =
      sample_ior(read_refractiveindex_file(path), SpectralGrid::visible(5.0), "Synthetic");
  EXPECT_DOUBLE_EQ(s.ior.ior[(450 - 360) / 5].real(), 1.25);
  EXPECT_DOUBLE_EQ(s.ior.ior[(450 - 360) / 5].imag(), 2.5);
  EXPECT_DOUBLE_EQ(s.ior.ior[0].real(), 1.0);      // clamped below 400 nm
  EXPECT_DOUBLE_EQ(s.ior.ior.back().imag(), 4.0);  // clamped above 600 nm
  ASSERT_EQ(s.warnings.size(), 1u);                // n and k share their coverage: one warning
  EXPECT_NE(s.warnings[0].find("360-395 and 605-830"), std::string::npos) << s.warnings[0];
}

TEST(Database, SeparateTabulatedNAndK) {
  test::TempDir tmp;
  const auto path =
      tmp.file("t.yml",
               "DATA:\n  - type: tabulated n\n    data: |\n        0.3 1.5\n        0.9 1.7\n"
               "  - type: tabulated k\n    data: |\n        0.3 0.0\n        0.9 0.6\n");
  const auto s = sample_ior(read_refractiveindex_file(path), SpectralGrid{600.0, 5.0, 1}, "x");
  EXPECT_DOUBLE_EQ(s.ior.ior[0].real(), 1.6);
  EXPECT_NEAR(s.ior.ior[0].imag(), 0.3, 1e-15);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(Database, CsvInput) {
  test::TempDir tmp;
  const auto path = tmp.file("m.csv", "lambda_nm,n,k\r\n300,0.5,3\r\n900,0.2,6\r\n");
  const auto s = sample_ior(read_nk_table(path), SpectralGrid{600.0, 5.0, 1}, "csv");
  EXPECT_DOUBLE_EQ(s.ior.ior[0].real(), 0.35);
  EXPECT_DOUBLE_EQ(s.ior.ior[0].imag(), 4.5);
}

void expect_input_error(const std::string& path, int line, const std::string& fragment) {
  try {
    sample_ior(read_refractiveindex_file(path), SpectralGrid::visible(5.0), "x");
    FAIL() << "no error for " << path;
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u)
        << "message must start with the file: " << e.what();
  }
}

TEST(Database, ErrorsNameFileLineAndProblem) {
  test::TempDir tmp;
  expect_input_error(
      tmp.file(
          "a.yml",
          "DATA:\n  - type: tabulated nk\n    data: |\n        0.4 1.0 2.0\n        0.5 x 2.0\n"),
      5, "'x' is not a finite number");
  expect_input_error(
      tmp.file(
          "b.yml",
          "DATA:\n  - type: tabulated nk\n    data: |\n        0.5 1.0 2.0\n        0.5 1.1 2.0\n"),
      5, "not strictly increasing");
  expect_input_error(
      tmp.file("c.yml",
               "DATA:\n  - type: formula 12\n    wavelength_range: 0.3 1\n    coefficients: 1\n"),
      2, "unknown formula type");
  expect_input_error(
      tmp.file("d.yml", "DATA:\n  - type: tabulated nk\n    data: |\n        0.4 1.0 2.0 7\n"), 4,
      "expected 3 columns, found 4");
  expect_input_error(
      tmp.file(
          "e.yml",
          "DATA:\n  - type: tabulated nk\n    data: |\n        2.0 1.0 2.0\n        3.0 1.0 2.0\n"),
      0, "does not cover any of 360-830 nm");
  expect_input_error(
      tmp.file("f.yml", "DATA:\n  - type: tabulated nk\n    data: |\n        0.4 -1.0 2.0\n"), 4,
      "not physical");
  expect_input_error(tmp.file("g.yml", "DATA: [\n"), 2, "invalid YAML");
}

// Every test that reads the database fails without it (none skips); this one says so in one line.
TEST(Database, IsFound) {
  const std::string data = std::string(FL_DEFAULT_DB) + "/data";
  ASSERT_TRUE(std::filesystem::is_directory(data))
      << "database not found (looked for " << data << ")";
}

TEST(Catalog, HasTheTalksTwentyEightMaterials) {
  const auto ms = read_catalog({FL_DEFAULT_DB, FL_MATERIALS});
  ASSERT_EQ(ms.size(), 28u);
  int metals = 0;
  for (const auto& m : ms) metals += m.material_class == MaterialClass::Metal;
  EXPECT_EQ(metals, 14);
  EXPECT_EQ(ms.front().name, "Silver");
  EXPECT_EQ(ms.back().name, "PET");
}

TEST(Catalog, ResolvesNamesPagesAndFiles) {
  const DataPaths paths{FL_DEFAULT_DB, FL_MATERIALS};
  EXPECT_EQ(resolve_material("gold", paths).name, "Gold");
  EXPECT_EQ(resolve_material("Cubic Zirconia", paths).key, "cubic_zirconia");
  const auto page = resolve_material("main/Au/nk/Johnson", paths);
  EXPECT_EQ(page.material_class, MaterialClass::Metal);
  EXPECT_THROW(resolve_material("unobtainium", paths), InputError);
}

}  // namespace
}  // namespace fl::spectral
