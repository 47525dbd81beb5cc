// The text inputs people have: tables with any reasonable header, refractiveindex.info's CSV
// download, SOPRA .nk files and Mitsuba/pbrt .spd pairs. Every variant holds the same data (n, k at
// 400, 500 and 700 nm), so each must read back the values written in it.
#include <gtest/gtest.h>

#include <string>

#include "spectral/nk_text.h"
#include "spectral/ri_database.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl::spectral {
namespace {

// At a tabulated wavelength the reader returns the file's own numbers; at 600 nm it interpolates
// linearly between the 500 and 700 nm rows: n = 0.7, k = 3.0.
constexpr double kExact = 1e-12;

void expect_reference_data(const OpticalConstants& oc, const std::string& what,
                           bool with_k = true) {
  const auto at = [&](double nm) {
    return sample_ior(oc, SpectralGrid{nm, 5.0, 1}, what).ior.ior[0];
  };
  EXPECT_NEAR(at(500.0).real(), 0.6, kExact) << what;
  EXPECT_NEAR(at(600.0).real(), 0.7, kExact) << what;
  EXPECT_NEAR(at(500.0).imag(), with_k ? 2.5 : 0.0, kExact) << what;
  EXPECT_NEAR(at(600.0).imag(), with_k ? 3.0 : 0.0, kExact) << what;
}

TEST(TextInputs, TablesWithAnyReasonableHeader) {
  test::TempDir tmp;
  const std::pair<const char*, const char*> cases[] = {
      {"a.csv", "Wavelength (nm),n,k\n400,0.5,2.0\n500,0.6,2.5\n700,0.8,3.5\n"},
      {"b.tsv", "WL [um]\tN\tK\n0.4\t0.5\t2.0\n0.5\t0.6\t2.5\n0.7\t0.8\t3.5\n"},
      {"c.txt", "# measured\nlambda_um   n   k\n0.4 0.5 2.0\n0.5   0.6 2.5\n0.7 0.8 3.5\n"},
      {"d.csv", " LAMBDA_NM , N , K \n400 , 0.5 , 2.0\n500,0.6,2.5\n700,0.8,3.5\n"},
      {"e.csv", "\"Wavelength, \xC2\xB5m\",\"n\",\"k\"\n0.4,0.5,2.0\n0.5,0.6,2.5\n0.7,0.8,3.5\n"},
      {"f.dat", "wavelength (\xCE\xBCm)  n  k\n0.4 0.5 2.0\n0.5 0.6 2.5\n0.7 0.8 3.5\n"},
      {"g.csv", "\xCE\xBB (nm),eta,kappa\n400,0.5,2.0\n500,0.6,2.5\n700,0.8,3.5\n"},
      {"h.csv", "k,n,wavelength_nm\n2.0,0.5,400\n2.5,0.6,500\n3.5,0.8,700\n"},
      {"i.csv", "Wavelength, nm,n,k\n400,0.5,2.0\n500,0.6,2.5\n700,0.8,3.5\n"},
  };
  for (const auto& [name, text] : cases)
    expect_reference_data(read_optical_file(tmp.file(name, text)), name);
}

TEST(TextInputs, KIsOptionalForDielectrics) {
  test::TempDir tmp;
  const auto oc =
      read_optical_file(tmp.file("n.csv", "wavelength_nm,n\n400,1.5\n500,1.6\n700,1.8\n"));
  ASSERT_EQ(oc.blocks.size(), 1u);
  EXPECT_EQ(oc.blocks[0].kind, DispersionBlock::Kind::TabulatedN);
  EXPECT_EQ(oc.blocks[0].n, (std::vector<double>{1.5, 1.6, 1.8}));
  // n below 1 in the visible without k is an absorbing material's n whose k column was dropped.
  EXPECT_THROW(read_optical_file(tmp.file("m.csv", "wavelength_nm,n\n400,0.5\n500,0.6\n700,0.8\n")),
               InputError);
}

// refractiveindex.info's "CSV" download: n rows under `wl,n`, then k rows under `wl,k`, in µm.
TEST(TextInputs, RefractiveIndexInfoCsvDownload) {
  test::TempDir tmp;
  const auto p =
      tmp.file("Johnson.csv", "wl,n\n0.4,0.5\n0.5,0.6\n0.7,0.8\nwl,k\n0.4,2.0\n0.5,2.5\n0.7,3.5\n");
  const auto oc = read_optical_file(p);
  ASSERT_EQ(oc.blocks.size(), 2u);
  EXPECT_EQ(oc.blocks[0].kind, DispersionBlock::Kind::TabulatedN);
  EXPECT_EQ(oc.blocks[1].kind, DispersionBlock::Kind::TabulatedK);
  expect_reference_data(oc, "download");
}

std::string error_of(const std::string& path) {
  try {
    sample_ior(read_optical_file(path), SpectralGrid::visible(5.0), "t");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A unit that the values contradict: wavelengths that miss the visible in the header's unit but
// would overlap it in the other.
TEST(TextInputs, HeaderUnitThatTheValuesContradictIsRefusedSayingSo) {
  test::TempDir tmp;
  const auto a = tmp.file("a.csv", "wavelength,n,k\n0.4,0.5,2.0\n0.7,0.8,3.5\n");
  EXPECT_NE(error_of(a).find(
                a + ":1: wavelengths 0.4-0.7 read in nm ('wavelength' names no unit, so nm) miss "
                    "360-830 nm, but in um they would overlap it"),
            std::string::npos)
      << error_of(a);
  const auto b = tmp.file("b.csv", "wavelength_um,n,k\n400,0.5,2.0\n700,0.8,3.5\n");
  EXPECT_NE(error_of(b).find("read in um (the header 'wavelength_um' says um)"), std::string::npos)
      << error_of(b);
}

// SOPRA: unit code, first and last value, intervals; then n, k pairs. In eV the points are 1.5, 2.5
// and 3.5 eV, at λ = hc/E with hc = 1239.841984 eV·nm (CODATA 2018).
TEST(TextInputs, SopraNkInElectronVoltsNanometresAndMicrometres) {
  test::TempDir tmp;
  const auto ev =
      read_optical_file(tmp.file("ev.nk", "1 1.5 3.5 2\n0.30 4.0\n0.40 3.0\n1.20 2.0\n"));
  const auto s = sample_ior(ev, SpectralGrid{1239.841984 / 2.5, 1.0, 1}, "ev").ior.ior[0];
  EXPECT_NEAR(s.real(), 0.40, kExact);
  EXPECT_NEAR(s.imag(), 3.0, kExact);
  EXPECT_NEAR(ev.blocks[0].min_nm, 1239.841984 / 3.5, 1e-9);
  // 400, 500, 600, 700 nm: the reference data with 600 nm given.
  expect_reference_data(
      read_optical_file(tmp.file("nm.nk", "4 400 700 3\n0.5 2.0\n0.6 2.5\n0.7 3.0\n0.8 3.5\n")),
      "nm");
  expect_reference_data(
      read_optical_file(tmp.file("um.nk", "2 0.4 0.7 3\n0.5;2.0;0.6;2.5\n0.7;3.0;0.8;3.5\n")),
      "um");
}

// Mitsuba (one pair per line, # comments) and pbrt (several pairs per line) spectra, in nm; either
// file of the pair names it.
TEST(TextInputs, SpdPairs) {
  test::TempDir tmp;
  tmp.file("Au.eta.spd", "# Gold, eta\n400 0.5\n500 0.6\n700 0.8\n");
  const auto k = tmp.file("Au.k.spd", "400 2.0 500 2.5\n700 3.5\n");
  expect_reference_data(read_optical_file(k), "k.spd");
  expect_reference_data(read_optical_file(tmp.path() + "/Au.eta.spd"), "eta.spd");
  // A lone NAME.eta.spd is a lossless material's n (k = 0)...
  const auto glass = read_optical_file(tmp.file("Glass.eta.spd", "400 1.5\n500 1.6\n700 1.8\n"));
  ASSERT_EQ(glass.blocks.size(), 1u);
  EXPECT_EQ(glass.blocks[0].kind, DispersionBlock::Kind::TabulatedN);
  EXPECT_EQ(glass.blocks[0].n, (std::vector<double>{1.5, 1.6, 1.8}));
  // ...unless n falls below 1 in the visible: a metal's n whose k file is missing.
  try {
    read_optical_file(tmp.file("Metal.eta.spd", "400 0.5\n500 0.6\n700 0.8\n"));
    ADD_FAILURE() << "a lone .eta.spd with n < 1 was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("n is 0.5 at 400 nm and there is no k"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fl::spectral
