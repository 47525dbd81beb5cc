// The exports for renderers, through the CLI: the OpenPBR table's rules and its dielectric IOR
// against published indices, the glTF materials as a glTF renderer reconstructs F0 from them, the
// out-of-range policy (gold's linear Rec.709 F0 stored in range at the ΔE2000 it reports, computed
// here with the published BT.709 matrix), and MaterialX documents in colour spaces MaterialX knows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "color/lab.h"
#include "csv_reader.h"
#include "test_util.h"

namespace fl {
namespace {

using Row = test::CsvRecord;

std::vector<Row> csv_rows(const std::string& text) {
  return test::csv_records(text);
}

std::string run_ok(const std::string& args) {
  const auto r = test::run_command(test::cli() + " -q " + args);
  EXPECT_EQ(r.status, 0) << args << ": " << r.err;
  return r.out;
}

// Published indices n_d (587.6 nm): Schott's BK7 datasheet 1.5168; diamond 2.4175 and water
// 1.3330 (20 °C), CRC Handbook. The exported index matches F0's luminance instead of one
// wavelength; dispersion puts the two within 0.01.
constexpr double kIorTolerance = 0.01;
// ACEScg's luminance row, ACES S-2014-004.
constexpr double kAp1Y[3] = {0.2722287168, 0.6740817658, 0.0536895174};

TEST(Exports, OpenPbrTableFollowsOpenPbrsRules) {
  const auto rows = csv_rows(run_ok("presets --openpbr --format csv"));
  const auto presets = csv_rows(run_ok("presets --format csv"));
  ASSERT_EQ(rows.size(), presets.size());
  const std::map<std::string, double> n_d{
      {"Glass BK7", 1.5168}, {"Diamond", 2.4175}, {"Water", 1.3330}};
  int dielectrics = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    if (presets[i].at("class") == "metal") {
      EXPECT_EQ(r.at("base_metalness"), "1") << r.at("material");
      EXPECT_EQ(r.at("base_color_r"), presets[i].at("f0_r"));
      continue;
    }
    ++dielectrics;
    EXPECT_EQ(r.at("base_metalness"), "0") << r.at("material");
    EXPECT_EQ(r.at("transmission_weight"), "1")
        << r.at("material");  // every catalog dielectric is clear
    const double eta = std::stod(r.at("specular_ior"));
    const double s = (eta - 1) / (eta + 1);
    double y = 0;
    for (int c = 0; c < 3; ++c)
      y += kAp1Y[c] * std::stod(presets[i].at(std::string("f0_") + "rgb"[c]));
    EXPECT_NEAR(s * s, y, 2e-6) << r.at("material");  // printed to 6 decimals
    if (n_d.count(r.at("material"))) {
      EXPECT_NEAR(eta, n_d.at(r.at("material")), kIorTolerance) << r.at("material");
    }
  }
  EXPECT_EQ(dielectrics, 14);
}

// The ACES white-free path: values derived in AP0 and converted to AP1 by OpenColorIO equal those
// derived in AP1 (the pipeline is linear and both spaces share the ACES white), to the printed
// digits.
std::vector<double> color_inputs(const std::string& doc, const std::string& input) {
  std::vector<double> v;
  const std::string key = "name=\"" + input + "\" type=\"color3\" value=\"";
  for (size_t p = doc.find(key); p != std::string::npos; p = doc.find(key, p + 1)) {
    const auto cells =
        test::csv_cells(doc.substr(p + key.size(), doc.find('"', p + key.size()) - p - key.size()));
    for (double x : test::csv_numbers(cells)) v.push_back(x);
  }
  return v;
}

TEST(Exports, MaterialxUsesMaterialxsColourSpaces) {
  const auto acescg = run_ok("presets --format mtlx");
  const auto ap0 = run_ok("--space aces2065-1 presets --format mtlx");
  EXPECT_NE(ap0.find("colorspace=\"acescg\""), std::string::npos);
  EXPECT_NE(ap0.find("converted to acescg"), std::string::npos);
  const auto a = color_inputs(acescg, "color0"), b = color_inputs(ap0, "color0");
  ASSERT_EQ(a.size(), 28u * 3);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 2e-6) << i;
  EXPECT_NE(run_ok("--space lin_p3d65 presets --format mtlx").find("colorspace=\"lin_displayp3\""),
            std::string::npos);
  EXPECT_NE(run_ok("--space lin_rec2020 presets --format mtlx --shader standard_surface")
                .find("colorspace=\"acescg\""),
            std::string::npos);
  const std::string config = std::string(FL_TESTS_DIR) + "/good_input/ocio/studio.ocio";
  EXPECT_NE(run_ok("--ocio-config '" + config + "' --space ACEScg presets --format mtlx")
                .find("colorspace=\"acescg\""),
            std::string::npos);
  const auto open_pbr = run_ok("presets --format mtlx --openpbr");
  EXPECT_NE(open_pbr.find("<open_pbr_surface name=\"diamond_shader\""), std::string::npos);
  EXPECT_EQ(open_pbr.find("generalized_schlick_bsdf"), std::string::npos);
}

// glTF's linear Rec.709: BT.709 RGB → XYZ (ITU-R BT.709, as in tests/color) and the D65 white.
const color::Mat3 kRec709{{0.4123907993, 0.3575843394, 0.1804807884, 0.2126390059, 0.7151686788,
                           0.0721923154, 0.0193308187, 0.1191947798, 0.9505321522}};
double de2000_rec709(const color::Rgb& a, const color::Rgb& b) {
  const color::Xyz white = kRec709 * color::Rgb{1, 1, 1};
  return color::ciede2000(color::xyz_to_lab(kRec709 * a, white),
                          color::xyz_to_lab(kRec709 * b, white));
}
color::Rgb rgb(const nlohmann::json& a) {
  return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()};
}

TEST(Exports, GltfMaterialsReproduceF0InRange) {
  const auto doc = nlohmann::json::parse(run_ok("--space lin_rec709 presets --format gltf"));
  const auto presets = csv_rows(run_ok("--space lin_rec709 presets --format csv"));
  ASSERT_EQ(doc["materials"].size(), presets.size());
  for (size_t i = 0; i < presets.size(); ++i) {
    const auto& m = doc.at("materials").at(i);
    const color::Rgb f0{std::stod(presets[i].at("f0_r")), std::stod(presets[i].at("f0_g")),
                        std::stod(presets[i].at("f0_b"))};
    const auto& pbr = m.at("pbrMetallicRoughness");
    for (int c = 0; c < 4; ++c) {
      EXPECT_GE(pbr["baseColorFactor"][c].get<double>(), 0.0);
      EXPECT_LE(pbr["baseColorFactor"][c].get<double>(), 1.0);
    }
    if (presets[i].at("class") == "metal") {
      EXPECT_EQ(pbr["metallicFactor"], 1);
      if (!presets[i].at("out_of_range").empty()) continue;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(pbr["baseColorFactor"][c].get<double>(), f0[c], 2e-6) << m["name"];
      continue;
    }
    // A glTF renderer's dielectric F0: ((ior − 1)/(ior + 1))² × specularColorFactor
    // (KHR_materials_specular).
    EXPECT_EQ(pbr["metallicFactor"], 0);
    const auto& ext = m.at("extensions");
    const double ior = ext.at("KHR_materials_ior").at("ior").get<double>(),
                 s = (ior - 1) / (ior + 1);
    const bool tinted = ext.contains("KHR_materials_specular");
    for (int c = 0; c < 3; ++c) {
      const double tint =
          tinted ? ext.at("KHR_materials_specular").at("specularColorFactor")[c].get<double>()
                 : 1.0;
      EXPECT_NEAR(s * s * tint, f0[c], 1e-3 * f0[c]) << m["name"] << " " << c;
    }
    EXPECT_EQ(ext.at("KHR_materials_transmission").at("transmissionFactor"), 1);
  }
}

// Gold's F0 is above 1 in linear Rec.709: glTF stores the nearest in-range colour, and the ΔE2000
// it reports is the one computed here; it beats both clipping each channel and scaling the colour
// down.
TEST(Exports, GltfOutOfRangePolicyOnGold) {
  const auto doc = nlohmann::json::parse(run_ok("--space lin_rec709 presets --format gltf"));
  const auto gold = std::find_if(doc["materials"].begin(), doc["materials"].end(),
                                 [](const auto& m) { return m["name"] == "Gold"; });
  ASSERT_NE(gold, doc["materials"].end());
  const auto& x = (*gold)["extras"]["fresnelLab"];
  EXPECT_EQ(x["out_of_range"], "f0_r");
  const color::Rgb truth = rgb(x["f0"]),
                   stored = rgb((*gold)["pbrMetallicRoughness"]["baseColorFactor"]);
  EXPECT_GT(truth.r, 1.0);
  const double de = de2000_rec709(truth, stored);
  EXPECT_NEAR(x["de00_stored"].get<double>(), de, 1e-3);
  const color::Rgb clipped{1.0, truth.g, truth.b},
      scaled{1.0, truth.g / truth.r, truth.b / truth.r};
  std::printf("gold lin_rec709 F0 stored in range: dE2000 %.4f (clipping %.4f, scaling %.4f)\n", de,
              de2000_rec709(truth, clipped), de2000_rec709(truth, scaled));
  EXPECT_LT(de, de2000_rec709(truth, clipped));
  EXPECT_LT(de, de2000_rec709(truth, scaled));
}

// The `doc` attributes of a MaterialX document, in order.
std::vector<std::string> doc_attributes(const std::string& mtlx) {
  std::vector<std::string> out;
  for (size_t p = mtlx.find(" doc=\""); p != std::string::npos; p = mtlx.find(" doc=\"", p + 1))
    out.push_back(mtlx.substr(p + 6, mtlx.find('"', p + 6) - p - 6));
  return out;
}

// Exports state where their data comes from and how much of 360-830 nm it measures, as the presets
// table does for the same materials: Chen's gold (its published data stops at 605 nm: coverage
// 0.86, extrapolated) and a lossless file measured over the whole range (coverage 1, no k data).
TEST(Exports, ProvenanceStatesSourceCoverageAndExtrapolation) {
  test::TempDir tmp;
  const std::string full = tmp.file("full.csv", "lambda_nm,n\n350,1.52\n600,1.51\n850,1.50\n");
  const std::string args =
      "--space lin_rec709 --min-coverage 0 presets main/Au/nk/Chen '" + full + "' --format ";
  const auto table = csv_rows(run_ok(args + "csv"));
  const auto mtlx = run_ok(args + "mtlx");
  const auto gltf = nlohmann::json::parse(run_ok(args + "gltf"));
  ASSERT_EQ(table.size(), 2u);
  constexpr double kIssueCoverage = 0.86, kIssueCoverageDigits = 0.005;
  EXPECT_NEAR(std::stod(table[0].at("coverage")), kIssueCoverage, kIssueCoverageDigits);
  EXPECT_EQ(table[0].at("extrapolated"), "yes");
  EXPECT_EQ(table[1].at("coverage"), "1.0000");
  EXPECT_EQ(table[1].at("extrapolated"), "no");
  const auto docs = doc_attributes(mtlx);
  ASSERT_EQ(docs.size(), 2u);
  ASSERT_EQ(gltf.at("materials").size(), 2u);
  // A file given by its absolute path is named by its file name: no path of the machine.
  const std::string sources[2] = {"main/Au/nk/Chen", "full.csv"};
  for (size_t i = 0; i < 2; ++i) {
    const auto& row = table[i];
    EXPECT_EQ(docs[i].rfind(row.at("material") + ": " + sources[i] + "; coverage " +
                                row.at("coverage") + " (n " + row.at("coverage_n") + ", k ",
                            0),
              0u)
        << docs[i];
    EXPECT_NE(docs[i].find("; extrapolated: " + row.at("extrapolated")), std::string::npos)
        << docs[i];
    const auto& x = gltf["materials"][i]["extras"]["fresnelLab"];
    EXPECT_EQ(x.at("source"), sources[i]);
    EXPECT_NEAR(x.at("coverage").get<double>(), std::stod(row.at("coverage")), 5e-5);
    EXPECT_NEAR(x.at("coverage_n").get<double>(), std::stod(row.at("coverage_n")), 5e-5);
    EXPECT_EQ(x.at("extrapolated").get<bool>(), row.at("extrapolated") == "yes");
    EXPECT_EQ(x.contains("uncovered"), row.at("extrapolated") == "yes");
  }
  // Chen: the held range is named; the lossless file has no k data.
  EXPECT_NE(docs[0].find("extrapolated: yes, n and k data does not cover 605-830 nm"),
            std::string::npos)
      << docs[0];
  EXPECT_TRUE(gltf["materials"][1]["extras"]["fresnelLab"].at("coverage_k").is_null());
  EXPECT_NE(docs[1].find("k not given"), std::string::npos) << docs[1];
  EXPECT_NE(mtlx.find("1 of 2 materials are extrapolated; the lowest coverage is " +
                      table[0].at("coverage") + " (main/Au/nk/Chen)"),
            std::string::npos);
  EXPECT_TRUE(gltf.at("asset").at("extras").at("fresnelLab").contains("coverage_policy"));
}

// Published ACES AP1 → linear Rec.709 matrix (ACES TB-2014-004, Bradford D60 → D65).
constexpr double kAp1ToRec709[9] = {1.70505,  -0.62179, -0.08326, -0.13026, 1.14080,
                                    -0.01055, -0.02400, -0.12897, 1.15297};

// In ACEScg the glTF document converts the colours to linear Rec.709 and says so: a metal's F0 (its
// stored colour, or the true value in its extras when that is outside [0, 1]) is the ACEScg
// preset's F0 through the published matrix.
TEST(Exports, GltfConvertsOtherSpaces) {
  const auto doc = nlohmann::json::parse(run_ok("presets --format gltf"));
  const auto presets = csv_rows(run_ok("presets --format csv"));
  ASSERT_EQ(doc.at("materials").size(), presets.size());
  EXPECT_NE(doc["asset"]["extras"]["fresnelLab"]
                .at("colour_space")
                .get<std::string>()
                .find("converted from acescg"),
            std::string::npos);
  int metals = 0;
  for (size_t i = 0; i < presets.size(); ++i) {
    if (presets[i].at("class") != "metal") continue;
    ++metals;
    const auto& m = doc["materials"][i];
    const auto& extras = m["extras"]["fresnelLab"];
    const auto f0 = extras.contains("f0") ? rgb(extras["f0"])
                                          : rgb(m["pbrMetallicRoughness"]["baseColorFactor"]);
    const double acescg[3] = {std::stod(presets[i].at("f0_r")), std::stod(presets[i].at("f0_g")),
                              std::stod(presets[i].at("f0_b"))};
    for (int c = 0; c < 3; ++c) {
      const double want = kAp1ToRec709[3 * c] * acescg[0] + kAp1ToRec709[3 * c + 1] * acescg[1] +
                          kAp1ToRec709[3 * c + 2] * acescg[2];
      EXPECT_NEAR(f0[c], want, 5e-4) << presets[i].at("material") << " channel " << c;
    }
  }
  EXPECT_GT(metals, 0);
}

// The flag's tolerance: lossless dielectrics' g (0 analytically, quadrature noise up to 2e-5) is
// not flagged; gold's F0 of 1.04 in linear Rec.709 is, in the CSV too.
TEST(Exports, OutOfRangeFlagsUseTheStatedTolerance) {
  for (const auto& r : csv_rows(run_ok("presets --format csv")))
    if (r.at("class") == "dielectric") {
      EXPECT_EQ(r.at("out_of_range"), "") << r.at("material");
    }
  for (const auto& r : csv_rows(run_ok("--space lin_rec709 presets --format csv")))
    if (r.at("material") == "Gold") {
      EXPECT_NE(r.at("out_of_range").find("f0_r"), std::string::npos);
    }
}

}  // namespace
}  // namespace fl
