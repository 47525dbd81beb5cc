// The `lut` command and `table lut-accuracy` through the CLI: files, determinism, bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/lut/lut.h"
#include "analysis/lut/lut_layout.h"
#include "fresnel/registered_models.h"
#include "io/exr.h"
#include "test_util.h"

namespace fl {
namespace {

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(LutCli, WritesTablesDeterministically) {
  test::TempDir tmp;
  const std::string lut = std::string("'") + FL_CLI + "' -q lut ";
  auto r = test::run_command(lut + "dfg --size 4 --samples 256 --out '" + tmp.path() + "/a.csv'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const auto csv = slurp(tmp.path() + "/a.csv");
  // Three comment lines (axes, channels, shader formula) per texture, the header, 16 rows.
  std::string dfg_header = "nov,perceptual_roughness,alpha", ltc_header = dfg_header;
  for (const auto& t : fresnel::kTermRegistry) {
    dfg_header += std::string(",") + t.dfg.channel;
    ltc_header += std::string(",") + t.ltc.channel;
  }
  const auto header = csv.find("\nnov,");
  ASSERT_NE(header, std::string::npos);
  EXPECT_EQ(csv.substr(header + 1, csv.find('\n', header + 1) - header - 1), dfg_header);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'),
            3 * static_cast<long>(analysis::term_texture_names(true).size()) + 17);
  r = test::run_command(lut + "dfg --size 4 --samples 256 --threads 1 --out '" + tmp.path() +
                        "/b.csv'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(tmp.path() + "/b.csv"), csv);

  r = test::run_command(lut + "dfg --size 4 --samples 256 --out '" + tmp.path() + "/dfg.h'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(tmp.path() + "/dfg.h")
                .find("static const float fresnel_lab_dfg_data[FRESNEL_LAB_DFG_SIZE * "
                      "FRESNEL_LAB_DFG_SIZE * FRESNEL_LAB_DFG_CHANNELS]"),
            std::string::npos);
  EXPECT_NE(slurp(tmp.path() + "/dfg_2.h").find("#define FRESNEL_LAB_DFG_2_SIZE 4\n"),
            std::string::npos);
  r = test::run_command(lut + "dfg --layout filament --size 4 --samples 256 --out '" + tmp.path() +
                        "/f.h'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(tmp.path() + "/f.h").find("static const uint16_t fresnel_lab_dfg_filament_data["),
            std::string::npos);

  // The DFG textures hold each channel where the layout (analysis/lut/lut_layout.h) says, which
  // the shaders and plans read: texel (0, 0) against the integrator at the first grid point.
  r = test::run_command(lut + "dfg --size 4 --samples 256 --out '" + tmp.path() + "/dfg.exr'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto grid = analysis::dfg_grid(4);
  const auto texel = analysis::integrate_dfg(grid.nov[0], grid.alpha[0], 256);
  for (const auto& tex : analysis::lut_textures()) {
    if (std::string(tex.lighting) != "ibl") continue;
    const auto dfg = io::read_exr(tmp.path() + "/" + tex.file);
    ASSERT_EQ(dfg.channels.size(), tex.channels.size()) << tex.name;  // a channel per term
    for (const auto& c : tex.channels) {
      std::string component = c.components;
      component[0] = static_cast<char>(std::toupper(component[0]));
      const auto k =
          std::find(dfg.channels.begin(), dfg.channels.end(), component) - dfg.channels.begin();
      ASSERT_LT(k, std::ssize(dfg.channels)) << component;
      const std::string name = c.channel;
      const auto term =
          std::find_if(fresnel::kTermRegistry.begin(), fresnel::kTermRegistry.end(),
                       [&](const fresnel::TermSpec& t) { return name == t.dfg.channel; });
      ASSERT_NE(term, fresnel::kTermRegistry.end()) << name;
      EXPECT_EQ(dfg.pixels[k], static_cast<float>(texel[term->term])) << name;
    }
  }

  r = test::run_command(lut + "ltc-moments --size 4 --samples 256 --out '" + tmp.path() +
                        "/m.csv'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto m = slurp(tmp.path() + "/m.csv");
  EXPECT_EQ(m.substr(0, m.find('\n')), ltc_header);

  r = test::run_command(lut + "ltc --size 4 --samples 256 --out '" + tmp.path() + "/ltc.exr'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto t1 = io::read_exr(tmp.path() + "/ltc_1.exr");
  EXPECT_EQ(t1.width, 4);
  EXPECT_EQ(t1.channels.size(), 4u);  // the matrix M⁻¹
  // A channel per table term of the texture (the term registry), and in ltc_2 the sphere form
  // factor after them.
  for (const auto& name : analysis::term_texture_names(false)) {
    size_t terms = 0;
    for (const auto& t : fresnel::kTermRegistry) terms += name == t.ltc.texture;
    EXPECT_EQ(io::read_exr(tmp.path() + "/" + name + ".exr").channels.size(),
              terms + (name == "ltc_2"))
        << name;
  }
  EXPECT_TRUE(std::filesystem::exists(tmp.path() + "/ltc.csv"));
}

TEST(LutCli, BadInputExitsTwoAndWritesNothing) {
  test::TempDir tmp;
  const std::string lut = std::string("'") + FL_CLI + "' lut ";
  for (const std::string args :
       {"dfg --size 1 --out x.csv", "dfg --size 4 --out x.txt", "ltc-moments --size 4 --out x.inc",
        "dfg --size 4 --out x.inc", "dfg --layout unreal --size 4 --out x.csv",
        "ltc --size 4 --samples 0 --out x.exr", "dfg --size 4", "frob --out x.csv"}) {
    const auto r = test::run_command("cd '" + tmp.path() + "' && " + lut + args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
  }
  EXPECT_TRUE(std::filesystem::is_empty(tmp.path()));
  for (const char* sub : {"", "dfg", "ltc-moments", "ltc"}) {
    const auto r = test::run_command(lut + sub + " --help");
    EXPECT_EQ(r.status, 0) << sub;
    EXPECT_NE(r.out.find(std::string(sub).empty() ? "ltc-moments" : "--out"), std::string::npos)
        << sub;
  }
}

// Every model × {ibl, area} for every material; pre-integrated F82 is no worse than pre-integrated
// Schlick for any metal, with the derived or the curve-fitted sets, under either lighting.
TEST(LutCli, PreIntegratedF82IsNoWorseThanSchlickForEveryMetal) {
  // The tables' own RMS ΔE2000 at 64² on endpoints: bilinear interpolation's error at that
  // spacing, at most about 0.006 under ibl and 0.014 under area, whose √(1 − n·v) axis is coarser
  // near grazing (texel centres: about 0.18, from the half texel at each edge).
  constexpr double kTableShare = 0.02;
  const auto r = test::run_command(test::cli() + " -q table lut-accuracy");
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream in(r.out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(
      line,
      "material,class,model,parameters,curve_rms_de00,ibl,ibl_rms_de00,ibl_max_de00,ibl_table_rms_"
      "de00,ibl_nv_rms_de00,ibl_hoffman_rms_de00,ibl_basis_rms_de00,area,area_rms_de00,area_max_"
      "de00,area_table_rms_de00,area_nv_rms_de00,area_hoffman_rms_de00,area_basis_rms_de00");
  std::map<std::string, std::array<double, 2>> schlick, f82;  // "material/parameters" → (ibl, area)
  std::set<std::string> metals, models;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string cell;
    std::vector<std::string> cells;
    while (std::getline(row, cell, ',')) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 19u) << line;
    // The 64² endpoint tables' own share of the error stays under a hundredth of a ΔE2000.
    EXPECT_LE(std::stod(cells[8]), kTableShare) << line;
    EXPECT_LE(std::stod(cells[15]), kTableShare) << line;
    models.insert(cells[2]);
    const bool tables =
        fresnel::model_from_name(cells[2]).pre_integration.ibl.fresnel_pre_integrated;
    EXPECT_EQ(cells[5], tables ? "tables" : "F(n·v) × lobe") << line;
    if (cells[1] != "metal" || cells[3] == "rendered") continue;
    metals.insert(cells[0]);
    const std::array<double, 2> e{std::stod(cells[6]), std::stod(cells[13])};
    if (cells[2] == "schlick") schlick[cells[0] + "/" + cells[3]] = e;
    if (cells[2] == "f82") f82[cells[0] + "/" + cells[3]] = e;
  }
  EXPECT_EQ(metals.size(), 14u);                            // the catalog's metals
  EXPECT_EQ(models.size(), fresnel::model_specs().size());  // every model
  ASSERT_EQ(schlick.size(), 28u);
  for (const auto& [key, s] : schlick) {
    ASSERT_TRUE(f82.count(key)) << key;
    std::printf("%-24s ibl schlick %.3f f82 %.3f | area schlick %.3f f82 %.3f\n", key.c_str(), s[0],
                f82[key][0], s[1], f82[key][1]);
    EXPECT_LE(f82[key][0], s[0]) << key << " (ibl)";
    EXPECT_LE(f82[key][1], s[1]) << key << " (area)";
  }
}

}  // namespace
}  // namespace fl
