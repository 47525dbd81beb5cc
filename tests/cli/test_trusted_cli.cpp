// Defaults a user can trust: short names resolve to the element's trusted value, named outlier
// pages warn, consensus exports carry their uncertainty, exports keep the F0 and F82 a render
// shows (absorbing semiconductors included), one name per material, and named materials that
// cannot be used are refused. Run through the CLI on the database pages named in each test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "analysis/pipeline/context.h"
#include "color/lab.h"
#include "csv_reader.h"
#include "fresnel/exact.h"
#include "test_util.h"

namespace fl {
namespace {

using test::cli;
using test::run_command;

// A colour written with six decimals and read back: within 0.01 ΔE2000 of the value it stands for.
constexpr double kExportF0Tolerance = 0.01;
// Distances printed with two decimals, compared between two outputs.
constexpr double kPrintedDe00 = 0.005;

const analysis::Context& acescg() {
  static const analysis::Context ctx{analysis::Settings{}};
  return ctx;
}

double de00(const color::Rgb& a, const color::Rgb& b) {
  return color::ciede2000<double>(acescg().rgb_to_lab(a), acescg().rgb_to_lab(b));
}

color::Rgb rgb(const nlohmann::json& a) {
  return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()};
}

// The spectral F0 and F82 of the presets table (ACEScg).
struct Spectral {
  color::Rgb f0, f82;
  std::string material_class;  // from the data
};
Spectral spectral(const std::string& page) {
  const auto r = run_command(cli() + " -q presets " + page);
  EXPECT_EQ(r.status, 0) << r.err;
  const auto row = test::csv_records(r.out).at(0);
  const auto v = [&](const std::string& c) { return std::stod(row.at(c)); };
  return {{v("f0_r"), v("f0_g"), v("f0_b")}, {v("f82_r"), v("f82_g"), v("f82_b")}, row.at("class")};
}

// `name="NAME" type="color3" value="r, g, b"` in a MaterialX document.
color::Rgb mtlx_color(const std::string& doc, const std::string& input) {
  const std::regex re("name=\"" + input +
                      "\" type=\"color3\" value=\"([-0-9.e]+), ([-0-9.e]+), ([-0-9.e]+)\"");
  std::smatch m;
  EXPECT_TRUE(std::regex_search(doc, m, re)) << input;
  return {std::stod(m[1]), std::stod(m[2]), std::stod(m[3])};
}

// Si, Ge and GaAs absorb in the visible (κ up to 5 at 400 nm); the catalog of the database files
// them as semiconductors, and Si is a dielectric by its mean κ.
// OpenPBR renders F0 = base_color and, at μ̄ = 1/7, F82 = specular_color × Schlick(F0, μ̄) (the
// F82-tint model's definition); glTF's metal renders F0 = baseColorFactor.
TEST(TrustedCli, AbsorbingSemiconductorsKeepTheirF0AndF82) {
  for (const std::string page : {"main/Si/nk/Aspnes", "main/Ge/nk/Aspnes", "main/GaAs/nk/Aspnes"}) {
    SCOPED_TRACE(page);
    const auto truth = spectral(page);
    const auto mtlx = run_command(cli() + " -q presets " + page + " --format mtlx --openpbr");
    ASSERT_EQ(mtlx.status, 0) << mtlx.err;
    EXPECT_NE(mtlx.out.find("name=\"base_metalness\" type=\"float\" value=\"1\""),
              std::string::npos);
    // Si is a dielectric by the data (mean κ 0.08 over 400-700 nm), Ge and GaAs metals.
    if (truth.material_class == "dielectric")
      EXPECT_NE(mtlx.out.find("written as a metal"), std::string::npos);
    const auto f0 = mtlx_color(mtlx.out, "base_color");
    EXPECT_LT(de00(f0, truth.f0), kExportF0Tolerance);
    const auto tint = mtlx_color(mtlx.out, "specular_color");
    const double w = std::pow(1 - 1.0 / 7.0, 5);
    color::Rgb f82;
    for (int c = 0; c < 3; ++c) f82[c] = tint[c] * (f0[c] + (1 - f0[c]) * w);
    EXPECT_LT(de00(f82, truth.f82), kExportF0Tolerance);
    // The dielectric form it replaces: a grey F0 and F82 of one index η (from F0's luminance),
    // more than 1 ΔE2000 from the spectral pair.
    const double y = (acescg().space().rgb_to_xyz * truth.f0).Y;
    const double eta = (1 + std::sqrt(y)) / (1 - std::sqrt(y));
    const double g0 = fresnel::fresnel_conductor(1.0, eta, 0.0);
    const double g82 = fresnel::fresnel_conductor(1.0 / 7.0, eta, 0.0);
    EXPECT_GT(std::max(de00({g0, g0, g0}, truth.f0), de00({g82, g82, g82}, truth.f82)), 1.0);
    const auto gltf =
        run_command(cli() + " -q presets " + page + " --format gltf --space lin_rec709");
    ASSERT_EQ(gltf.status, 0) << gltf.err;
    const auto doc = nlohmann::json::parse(gltf.out);
    const auto& m = doc["materials"][0];
    EXPECT_EQ(m["pbrMetallicRoughness"]["metallicFactor"], 1);
    // glTF's colours are linear Rec.709: against the spectral F0 in that working space.
    const auto rec709 = run_command(cli() + " -q --space lin_rec709 presets " + page);
    const auto row = test::csv_records(rec709.out).at(0);
    const color::Rgb want{std::stod(row.at("f0_r")), std::stod(row.at("f0_g")),
                          std::stod(row.at("f0_b"))};
    analysis::Settings s;
    s.space = "lin_rec709";
    const analysis::Context ctx709(s);
    const auto base = rgb(m["pbrMetallicRoughness"]["baseColorFactor"]);
    EXPECT_LT(color::ciede2000<double>(ctx709.rgb_to_lab(base), ctx709.rgb_to_lab(want)),
              kExportF0Tolerance);
  }
}

// Short names give the element's trusted value and say which and why: gold's ten bulk pages agree
// (consensus); titanium's four disagree (its recommended page). The distances the notes quote are
// those of `consensus --table pages`, a separate table of the same pages.
TEST(TrustedCli, ShortNamesResolveToTheTrustedValue) {
  const auto r = run_command(cli() + " presets gold titanium --format gltf");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("gold: the consensus of main/Au"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("titanium: main/Ti/nk/"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the recommended page of main/Ti"), std::string::npos) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  const auto& gold = doc["materials"][0];
  EXPECT_EQ(gold["name"], "Gold");
  const auto& basis = gold["extras"]["fresnelLab"]["consensus"];
  EXPECT_GE(basis["pages"].get<int>(), 3);
  EXPECT_LE(basis["f0_de00_median"].get<double>(), 2.0);
  const auto& ti = doc["materials"][1];
  EXPECT_EQ(ti["name"], "Titanium");
  EXPECT_FALSE(ti["extras"]["fresnelLab"].contains("consensus"));
  // Johnson's gold (the talk's page) against the consensus, as the pages table gives it.
  const auto pages = run_command(cli() + " -q consensus Au --table pages");
  ASSERT_EQ(pages.status, 0) << pages.err;
  double f0 = NAN;
  for (const auto& row : test::csv_records(pages.out))
    if (row.at("page") == "main/Au/nk/Johnson") f0 = std::stod(row.at("f0_de00"));
  ASSERT_FALSE(std::isnan(f0));
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m,
                                std::regex("main/Au/nk/Johnson \\(the talk's\\) is F0 ([0-9.]+)")));
  EXPECT_NEAR(std::stod(m[1]), f0, kPrintedDe00);
}

// A page named on its own that is an outlier of its element's consensus warns once, with its
// distance; one that is not, does not.
TEST(TrustedCli, NamedOutlierPagesWarnOnce) {
  const auto r =
      run_command(cli() + " presets main/Au/nk/Johnson main/Au/nk/Johnson main/Au/nk/Magnozzi-25C");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string w = "warning: main/Au/nk/Johnson is an outlier of the consensus of main/Au";
  const auto first = r.err.find(w);
  ASSERT_NE(first, std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(w, first + 1), std::string::npos);
  EXPECT_EQ(r.err.find("Magnozzi-25C is an outlier"), std::string::npos);
}

// Consensus exports carry the pages, the spread and each channel's bounds; one page is labelled.
TEST(TrustedCli, ConsensusExportsCarryTheirUncertainty) {
  const auto mtlx = run_command(cli() + " -q presets --consensus Au --consensus Cr --format mtlx");
  ASSERT_EQ(mtlx.status, 0) << mtlx.err;
  EXPECT_NE(mtlx.out.find("surfacematerial name=\"gold\""), std::string::npos);
  EXPECT_NE(mtlx.out.find("consensus of 10 bulk pages: ΔE2000 from it F0 median"),
            std::string::npos);
  EXPECT_NE(mtlx.out.find("a single bulk page, not a consensus"), std::string::npos);
  const auto gltf = run_command(cli() + " -q presets --consensus Au --consensus Cr --format gltf");
  const auto doc = nlohmann::json::parse(gltf.out);
  const auto& au = doc["materials"][0]["extras"]["fresnelLab"]["consensus"];
  EXPECT_EQ(au["pages"], 10);
  EXPECT_GE(au["f0_de00_max"].get<double>(), au["f0_de00_median"].get<double>());
  const auto lo = rgb(au["f0_lo"]), hi = rgb(au["f0_hi"]);
  for (int c = 0; c < 3; ++c) EXPECT_LT(lo[c], hi[c]);
  EXPECT_EQ(doc["materials"][1]["extras"]["fresnelLab"]["consensus"]["single_page"], true);
}

// Lead: a page used by its consensus is extrapolated, so the consensus is.
TEST(TrustedCli, ConsensusExtrapolationPropagates) {
  const auto r = run_command(cli() + " -q presets --consensus Pb --format mtlx");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("extrapolated: yes"), std::string::npos);
}

TEST(TrustedCli, RoughnessIsWrittenAndSettable) {
  const auto def = nlohmann::json::parse(run_command(cli() + " -q presets gold --format gltf").out);
  EXPECT_DOUBLE_EQ(def["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"].get<double>(),
                   0.3);
  const auto set =
      run_command(cli() + " -q presets silver --format mtlx --roughness 0.5 --openpbr");
  EXPECT_NE(set.out.find("name=\"specular_roughness\" type=\"float\" value=\"0.5\""),
            std::string::npos);
  const auto bsdf = run_command(cli() + " -q presets silver --format mtlx --roughness 0.5");
  EXPECT_NE(bsdf.out.find("name=\"roughness\" type=\"vector2\" value=\"0.25, 0.25\""),
            std::string::npos);
  EXPECT_EQ(run_command(cli() + " -q presets silver --format gltf --roughness 2").status, 2);
}

// One material, one name: a file is named by its stem in every format, a second file of that
// stem is NAME_2 everywhere, and no absolute path is written.
TEST(TrustedCli, FilesAreNamedByTheirStemWithoutPaths) {
  test::TempDir tmp;
  std::filesystem::create_directories(tmp.path() + "/a");
  std::filesystem::create_directories(tmp.path() + "/b");
  const std::string data = "Wavelength (nm),n,k\n350,0.3,3.0\n850,0.2,5.0\n";
  const auto a = tmp.file("a/Cu.csv", data), b = tmp.file("b/Cu.csv", data);
  const std::string files = " '" + a + "' '" + b + "'";
  const auto csv = run_command(cli() + " -q presets" + files);
  ASSERT_EQ(csv.status, 0) << csv.err;
  const auto rows = test::csv_records(csv.out);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("material"), "Cu");
  EXPECT_EQ(rows[1].at("material"), "Cu_2");
  for (const char* f : {"mtlx", "gltf"}) {
    const auto r = run_command(cli() + " -q presets" + files + " --format " + f);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.find(tmp.path()), std::string::npos) << f;
    EXPECT_NE(r.out.find("Cu_2"), std::string::npos) << f;
  }
}

// Cs/Monin covers 0.938 of the visible: named, it is refused (exit 2) unless --skip-unusable; a
// glob skips it and the document says so even under -q.
TEST(TrustedCli, NamedUnusableMaterialsAreErrors) {
  EXPECT_EQ(run_command(cli() + " -q presets silver main/Cs/nk/Monin").status, 2);
  const auto skip =
      run_command(cli() + " -q --skip-unusable presets silver main/Cs/nk/Monin --format gltf");
  ASSERT_EQ(skip.status, 0) << skip.err;
  const auto doc = nlohmann::json::parse(skip.out);
  EXPECT_EQ(doc["asset"]["extras"]["fresnelLab"]["skipped"].size(), 1u);
  const auto glob = run_command(cli() + " -q presets silver 'main/Cs/nk/Mon*' --format mtlx");
  ASSERT_EQ(glob.status, 0) << glob.err;
  EXPECT_NE(glob.out.find("Skipped 1 material: main/Cs/nk/Monin: covers 0.938"), std::string::npos);
}

TEST(TrustedCli, ConsensusErrorsNameNoFlagThatWasNotUsed) {
  const auto r = run_command(cli() + " consensus steel");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.find("--consensus"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'steel'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fl
