// The text inputs people have: tables with any reasonable header, refractiveindex.info's CSV
// download, SOPRA .nk files and Mitsuba/pbrt .spd pairs. Every variant holds the same data (n, k at
// 400, 500 and 700 nm), so each must read back the values written in it.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "spectral/nk_text.h"
#include "spectral/ri_database.h"
#include "spectral/text_file.h"
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

// Photon energies: λ = hc / E with hc = 1239.841984 eV·nm (CODATA 2018). Rows listed by increasing
// energy are read in increasing wavelength: 3.5, 2.5, 1.5 eV are 354.24, 495.94, 826.56 nm.
constexpr double kHc = 1239.841984;

void expect_energy_data(const OpticalConstants& oc, const std::string& what) {
  ASSERT_EQ(oc.blocks.size(), 1u) << what;
  const auto& b = oc.blocks[0];
  EXPECT_EQ(b.n, (std::vector<double>{1.20, 0.40, 0.30})) << what;
  EXPECT_EQ(b.k, (std::vector<double>{2.0, 3.0, 4.0})) << what;
  EXPECT_NEAR(b.min_nm, kHc / 3.5, 1e-9) << what;
  EXPECT_NEAR(b.max_nm, kHc / 1.5, 1e-9) << what;
  // Linear in wavelength between the 2.5 and 1.5 eV rows: halfway, n = 0.35 and k = 3.5.
  const double mid = (kHc / 2.5 + kHc / 1.5) / 2;
  const auto s = sample_ior(oc, SpectralGrid{mid, 1.0, 1}, what).ior.ior[0];
  EXPECT_NEAR(s.real(), 0.35, kExact) << what;
  EXPECT_NEAR(s.imag(), 3.5, kExact) << what;
}

TEST(TextInputs, EnergyColumnsInElectronVolts) {
  test::TempDir tmp;
  const std::pair<const char*, const char*> cases[] = {
      {"a.csv", "Energy (eV),n,k\n1.5,0.30,4.0\n2.5,0.40,3.0\n3.5,1.20,2.0\n"},
      {"b.txt", "eV n k\n3.5 1.20 2.0\n2.5 0.40 3.0\n1.5 0.30 4.0\n"},  // decreasing energies
      {"c.tsv", "Photon energy [eV]\tn\tk\n1.5\t0.30\t4.0\n2.5\t0.40\t3.0\n3.5\t1.20\t2.0\n"},
      {"d.csv", "n,k,E_eV\n0.30,4.0,1.5\n0.40,3.0,2.5\n1.20,2.0,3.5\n"},
  };
  for (const auto& [name, text] : cases)
    expect_energy_data(read_optical_file(tmp.file(name, text)), name);
  // An energy column must say eV; zero is no photon energy.
  EXPECT_NE(
      error_of(tmp.file("e.csv", "energy,n,k\n1.5,0.3,4\n")).find("column 'energy' names no unit"),
      std::string::npos);
  EXPECT_NE(error_of(tmp.file("f.csv", "eV,n,k\n0,0.3,4\n2.5,0.4,3\n"))
                .find("photon energy 0 eV must be positive"),
            std::string::npos);
}

// Spreadsheets in locales with a decimal comma: semicolons between columns, "0,5" for 0.5; also
// a decimal comma between tabs or spaces, or inside a quoted CSV field.
TEST(TextInputs, DecimalCommas) {
  test::TempDir tmp;
  const std::pair<const char*, const char*> cases[] = {
      {"a.csv", "Wavelength (nm);n;k\n400;0,5;2,0\n500;0,6;2,5\n700;0,8;3,5\n"},
      {"b.csv", "wl_um;n;k\n0,4;0,5;2\n0,5;0,6;2,5\n0,7;0,8;3,5\n"},
      {"c.tsv", "lambda_nm\tn\tk\n400\t0,5\t2,0\n500\t0,6\t2,5\n700\t0,8\t3,5\n"},
      {"d.txt", "lambda_nm n k\n400 0,5 2,0\n500 0,6 2,5\n700 0,8 3,5\n"},
      {"e.csv",
       "\"lambda_nm\",\"n\",\"k\"\n\"400\",\"0,5\",\"2,0\"\n500,\"0,6\",\"2,5\"\n700,\"0,8\",\"3,"
       "5\"\n"},
      {"f.csv",
       "wavelength_nm;n;k\n400;0.5;2.0\n500;0.6;2.5\n700;0.8;3.5\n"},  // points, semicolons
      {"g.csv", "eV;n;k\n1,5;0,30;4\n2,5;0,40;3\n3,5;1,20;2\n"},
  };
  for (const auto& [name, text] : cases) {
    const auto oc = read_optical_file(tmp.file(name, text));
    if (std::string(name) == "g.csv")
      expect_energy_data(oc, name);
    else
      expect_reference_data(oc, name);
  }
  // One file, one decimal mark: "1,234" beside "0.5" could be a thousands separator.
  const auto mixed =
      tmp.file("m.csv", "wavelength_nm;n;k\n400;0,5;2,0\n500;0.6;2.5\n700;0,8;3,5\n");
  EXPECT_NE(
      error_of(mixed).find(mixed + ":3: '0.6' has a decimal point but line 2 has a decimal comma"),
      std::string::npos)
      << error_of(mixed);
  // Decimal commas in a comma-separated file split every value in two.
  const auto split = tmp.file("s.csv", "wavelength_nm,n,k\n400,0,5,2,0\n500,0,6,2,5\n");
  EXPECT_NE(error_of(split).find("expected 3 columns, found 5 (with decimal commas, separate the "
                                 "columns with ';' or tabs)"),
            std::string::npos)
      << error_of(split);
}

// J.A. Woollam WVASE material files: name, unit, type, then rows.
TEST(TextInputs, WvaseMatFiles) {
  test::TempDir tmp;
  expect_reference_data(
      read_optical_file(
          tmp.file("nm.mat", "Au (test)\nnm\nNK\n400 0.5 2.0\n500\t0.6\t2.5\n700 0.8 3.5\n")),
      "nm");
  expect_reference_data(read_optical_file(tmp.file(
                            "um.mat", "Au\n  um\nnk\n0.4 0.5 2.0\n0.5 0.6 2.5\n0.7 0.8 3.5\n")),
                        "um");
  expect_reference_data(
      read_optical_file(tmp.file("a.mat", "Au\nA\nNK\n4000 0.5 2.0\n5000 0.6 2.5\n7000 0.8 3.5\n")),
      "angstrom");
  expect_energy_data(read_optical_file(tmp.file(
                         "ev.mat", "Au\neV\nNK\n1.5 0.30 4.0\n2.5 0.40 3.0\n3.5 1.20 2.0\n")),
                     "eV");
  // A row count in place of the type (CompleteEASE's variant) is checked.
  expect_reference_data(read_optical_file(tmp.file(
                            "count.mat", "Au\nnm\n3\n400 0.5 2.0\n500 0.6 2.5\n700 0.8 3.5\n")),
                        "count");
  EXPECT_NE(error_of(tmp.file("count2.mat", "Au\nnm\n4\n400 0.5 2.0\n700 0.8 3.5\n"))
                .find(":3: the header's row count is 4, but 2 rows follow"),
            std::string::npos);
  // E1E2: ε = (n + ik)², so n = 0.5, k = 2 is ε = -3.75 + 2i; 0.6 + 2.5i is -5.89 + 3i;
  // 0.8 + 3.5i is -11.61 + 5.6i; a lossless 1.5 is 2.25 + 0i.
  expect_reference_data(
      read_optical_file(
          tmp.file("e.mat", "Au\nnm\nE1E2\n400 -3.75 2.0\n500 -5.89 3.0\n700 -11.61 5.6\n")),
      "E1E2");
  const auto glass =
      read_optical_file(tmp.file("g.mat", "BK7\nnm\nE1E2\n400 2.25 0\n500 2.25 0\n700 2.25 0\n"));
  EXPECT_EQ(glass.blocks[0].n, (std::vector<double>{1.5, 1.5, 1.5}));
  EXPECT_EQ(glass.blocks[0].k, (std::vector<double>{0.0, 0.0, 0.0}));
  // A MATLAB .mat shares the extension.
  std::string matlab = "MATLAB 5.0 MAT-file, Platform: GLNXA64";
  matlab += std::string("\0\x01\x02", 3);
  EXPECT_NE(error_of(tmp.file("m.mat", matlab))
                .find(":1: a MATLAB .mat file (binary), not a J.A. Woollam WVASE material file"),
            std::string::npos);
}

// The exports people have: a semicolon table whose wavelengths use a decimal point and whose n, k
// use decimal commas (each column keeps one mark), a trailing separator on every line, a
// Windows-1252 µm (the byte 0xB5), and SOPRA with decimal commas (the header's too).
TEST(TextInputs, SpreadsheetAndLocaleExports) {
  test::TempDir tmp;
  expect_reference_data(
      read_optical_file(tmp.file("a.csv",
                                 "wavelength_nm;n;k\n400.0;0,5;2,0\n500.0;0,6;2,5\n"
                                 "700.0;0,8;3,5\n")),
      "semicolon, mixed marks");
  expect_reference_data(
      read_optical_file(tmp.file("b.csv", "wl,n,k,\n0.4,0.5,2.0,\n0.5,0.6,2.5,\n0.7,0.8,3.5,\n")),
      "trailing separator");
  expect_reference_data(
      read_optical_file(tmp.file("c.txt",
                                 "Wavelength (\xB5m)\tn\tk\n0.4\t0.5\t2.0\n0.5\t0.6\t2.5\n"
                                 "0.7\t0.8\t3.5\n")),
      "Windows-1252 micro sign");
  expect_reference_data(
      read_optical_file(tmp.file("d.nk", "2 0,4 0,7 3\n0,5 2,0\n0,6 2,5\n0,7 3,0\n0,8 3,5\n")),
      "SOPRA, decimal commas");
  expect_reference_data(
      read_optical_file(tmp.file("e.nk", "4 400 700 3\n0.5, 2.0\n0.6,2.5\n0,7;3,0\n0.8 3.5\n")),
      "SOPRA, commas between values");
  // 0xB5 continuing a UTF-8 character ("õ" is C3 B5) is no micro sign: "wõ" is no wavelength.
  EXPECT_NE(error_of(tmp.file("f.csv", "w\xC3\xB5,n,k\n0.4,0.5,2.0\n")).find("is not a wavelength"),
            std::string::npos);
  // In one column the marks must agree.
  EXPECT_NE(error_of(tmp.file("g.csv", "wavelength_nm;n;k\n400;0,5;2,0\n500;0.6;2,5\n"))
                .find("a column must use one decimal mark"),
            std::string::npos);
}

// SOPRA's count is of intervals: a file listing as many pairs as the count says is one short.
TEST(TextInputs, SopraCountOfIntervalsIsExplained) {
  test::TempDir tmp;
  const auto e = error_of(tmp.file("p.nk", "4 400 700 3\n0.5 2.0\n0.6 2.5\n0.8 3.5\n"));
  EXPECT_NE(
      e.find(":4: expected 8 values (4 n, k pairs), found 6: the first line's count 3 is of "
             "intervals between FIRST and LAST, so the file holds 3 + 1 points (for 3 points, "
             "write 2)"),
      std::string::npos)
      << e;
}

}  // namespace
}  // namespace fl::spectral

namespace fl {
namespace {

TEST(TextInputs, FieldsSplitIntoASpanAreCountedBeyondIt) {
  std::array<std::string_view, 3> fields;
  EXPECT_EQ(spectral::split_fields(" 0.5,\t1.25  3 ,4", " \t,", fields), 4u);
  EXPECT_EQ(fields[0], "0.5");
  EXPECT_EQ(fields[1], "1.25");
  EXPECT_EQ(fields[2], "3");
  EXPECT_EQ(spectral::split_fields(" ,\t", " \t,", fields), 0u);
  EXPECT_EQ(spectral::split_fields("7", " \t,", fields), 1u);
  EXPECT_EQ(fields[0], "7");
}

}  // namespace
}  // namespace fl
