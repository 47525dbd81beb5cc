// `basis` through the CLI on a few database pages: its files, nested projections that never lose
// accuracy with more terms, and bad input refused with nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "csv_reader.h"
#include "test_util.h"

namespace fl {
namespace {

using test::cli;
using test::run_command;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(BasisCli, WritesTheBasisOfTheMatchedPages) {
  test::TempDir tmp;
  const std::string out = tmp.path() + "/basis";
  const auto r =
      run_command(cli() + " basis 'main/Au/nk/*' 'main/Cu/nk/*' 'main/SiO2/nk/*' --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* f :
       {"basis.md", "basis_functions.csv", "basis_polynomials.csv", "basis_energy.csv",
        "basis_projection.csv", "basis_pages.csv", "basis_polynomials.h"})
    EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << f;
  EXPECT_NE(slurp(out + "/basis_polynomials.h").find("kBasisPolyTerms = 4;"), std::string::npos);
  // Each page's least-squares residual over nested spans never grows with K (5 decimals printed).
  const auto pages = test::csv_records(slurp(out + "/basis_pages.csv"));
  ASSERT_FALSE(pages.empty());
  for (const auto& p : pages)
    for (int k = 3; k <= 5; ++k)
      EXPECT_LE(std::stod(p.at("refl_rms_k" + std::to_string(k))),
                std::stod(p.at("refl_rms_k" + std::to_string(k - 1))))
          << p.at("page") << " K=" << k;
  EXPECT_NE(r.err.find("basis: "), std::string::npos) << "progress on stderr";
}

// Σ over a class's pages of the squared RMS reflectance residual at K = 3: proportional to the
// class's residual energy (every page has the same wavelengths and samples).
std::map<std::string, double> class_energy(const std::string& pages_csv) {
  std::map<std::string, double> e;
  for (const auto& p : test::csv_records(pages_csv))
    e[p.at("class")] += std::pow(std::stod(p.at("refl_rms_k3")), 2);
  return e;
}

// With the SVD construction, one data term is the weighted stack's leading singular vector: it
// minimizes the weighted residual energy w_m·E_metal + w_d·E_dielectric over all choices. Weighing
// the classes alike raises the metals' weight relative to the pages-alike construction (2 metal
// pages against some 25 dielectric pages here), so adding the two optimality inequalities, the
// metals' residual energy cannot grow and the dielectrics' cannot shrink.
TEST(BasisCli, WeighingTheClassesShiftsTheResidualToTheMajority) {
  test::TempDir tmp;
  std::map<std::string, std::map<std::string, double>> energy;
  for (const char* weighting : {"pages", "classes"}) {
    const std::string out = tmp.path() + "/" + weighting;
    const auto r =
        run_command(cli() +
                    " -q basis 'main/Au/nk/Johnson' 'main/Cu/nk/Johnson' "
                    "'main/SiO2/nk/*' 'main/TiO2/nk/*' --construction svd --terms 1 --weighting " +
                    weighting + " --out " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    energy[weighting] = class_energy(slurp(out + "/basis_pages.csv"));
  }
  ASSERT_GT(energy["pages"]["metal"], 0);
  // The CSV rounds each RMS to 5 decimals: a relative slack of 1e-3 on sums of squares.
  EXPECT_LE(energy["classes"]["metal"], energy["pages"]["metal"] * (1 + 1e-3));
  EXPECT_GE(energy["classes"]["dielectric"], energy["pages"]["dielectric"] * (1 - 1e-3));
  EXPECT_LT(energy["classes"]["metal"], energy["pages"]["metal"]);
}

TEST(BasisCli, RefusesBadInputWritingNothing) {
  test::TempDir tmp;
  const std::string out = tmp.path() + "/basis";
  for (const std::string& args :
       {" basis --terms 0 --out " + out, " basis 'main/NoSuchBook/*' --out " + out,
        " basis --weighting heavy --out " + out, " basis --metal-share 1.5 --out " + out,
        " basis --construction magic --out " + out, " basis --terms 2 --out " + out}) {
    const auto r = run_command(cli() + args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << args;
  }
  const auto help = run_command(cli() + " basis --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("--out"), std::string::npos);
  EXPECT_NE(help.out.find("--degree"), std::string::npos);
  EXPECT_NE(help.out.find("--weighting"), std::string::npos);
  EXPECT_NE(help.out.find("--construction"), std::string::npos);
}

}  // namespace
}  // namespace fl
