// What an engine ships, through the CLI: the C headers of every lookup table compile together (two
// tables, and the same table under two symbols, in one translation unit) as C99 and as C++ with
// -Wall -Wextra -pedantic -Werror, and hold the values of the CSV files of the same tables; the
// `--standalone` shaders of `shader` and `plan --shader` compile with glslangValidator (GLSL and
// its HLSL front end) and validate with spirv-val; the size a shader maps its LTC uv with is the
// size of the table `lut` writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/lut/lut_layout.h"
#include "csv_reader.h"
#include "fresnel/table_terms.h"
#include "test_util.h"

namespace fl {
namespace {

std::string lut(const std::string& args) {
  return test::cli() + " -q lut " + args;
}

// A header's symbol (for NAME_data, NAME_SIZE, NAME_CHANNELS) and file.
struct Header {
  std::string symbol, file;
};

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// A program valid as C99 and C++ printing, per header, "symbol size channels v0 v1 ..." (texel 0).
std::string program(const std::vector<Header>& headers, const Header& half) {
  std::string s = "#include <stdio.h>\n";
  for (const auto& h : headers) s += "#include \"" + h.file + "\"\n";
  s += "#include \"" + half.file + "\"\n";
  s += R"(
static void show(const char* name, int size, int channels, const float* data) {
  int c;
  printf("%s %d %d", name, size, channels);
  for (c = 0; c < channels; ++c) printf(" %.9g", data[c]);
  printf("\n");
}

int main(void) {
)";
  for (const auto& h : headers) {
    const std::string m = upper(h.symbol);
    s += "  show(\"" + h.symbol + "\", " + m + "_SIZE, " + m + "_CHANNELS, " + h.symbol +
         "_data);\n";
  }
  const std::string m = upper(half.symbol);
  s += "  printf(\"" + half.symbol + " %d %d %u\\n\", " + m + "_SIZE, " + m +
       "_CHANNELS, (unsigned)" + half.symbol + "_data[0]);\n  return 0;\n}\n";
  return s;
}

// The first row of a CSV file (comments skipped) by column.
test::CsvRecord first_row(const std::string& path) {
  const auto rows = test::csv_records(test::read_text_file(path), {.skip_comments = true});
  return rows.empty() ? test::CsvRecord{} : rows[0];
}

// A table's texture number k's suffix in the names of its files and symbols: none for the first
// (the --out path), else the texture's (dfg_2 → _2), as `lut` writes them.
std::string texture_suffix(const std::string& texture, size_t k) {
  return k == 0 ? "" : texture.substr(texture.find('_'));
}
std::string texture_suffix(const std::string& texture, const std::vector<std::string>& textures) {
  const size_t k = std::find(textures.begin(), textures.end(), texture) - textures.begin();
  return texture_suffix(texture, k);
}

// The component index of "r", "g", "b", "a".
size_t component(const char* c) {
  return std::string("rgba").find(c[0]);
}

TEST(ShippingCli, TableHeadersCompileTogetherAsCAndCxx) {
  test::TempDir dir;
  const std::string d = dir.path() + "/";
  const std::string small = " --size 4 --samples 256 --threads 1 --out '" + d;
  for (const std::string& args :
       {"dfg" + small + "dfg.h'", "dfg" + small + "dfg.csv'",
        "dfg --symbol my_dfg" + small + "mine.h'", "ltc-moments" + small + "moments.h'",
        "ltc-moments" + small + "moments.csv'", "ltc" + small + "ltc.h'",
        "ltc" + small + "ltc.csv'", "energy" + small + "energy.h'",
        "energy" + small + "energy.csv'", "dfg --layout filament" + small + "filament.h'",
        "energy --dielectric --slices 4" + small + "dielectric.h'",
        "energy --dielectric --slices 4" + small + "dielectric.csv'"}) {
    const auto r = test::run_command(lut(args));
    ASSERT_EQ(r.status, 0) << args << ": " << r.err;
  }
  // The table terms' textures (from the term registry): the DFG ones under two symbols, the LTC
  // moments alone and beside the matrix; then the energy tables.
  const auto dfg_textures = analysis::term_texture_names(true),
             ltc_textures = analysis::term_texture_names(false);
  std::vector<Header> headers;
  for (size_t k = 0; k < dfg_textures.size(); ++k) {
    const std::string s = texture_suffix(dfg_textures[k], k);
    headers.push_back({"fresnel_lab_dfg" + s, "dfg" + s + ".h"});
    headers.push_back({"my_dfg" + s, "mine" + s + ".h"});
  }
  for (size_t k = 0; k < ltc_textures.size(); ++k) {
    const std::string s = texture_suffix(ltc_textures[k], k);
    headers.push_back({"fresnel_lab_ltc_moments" + s, "moments" + s + ".h"});
  }
  headers.push_back({"fresnel_lab_ltc_1", "ltc_1.h"});
  for (const auto& name : ltc_textures) headers.push_back({"fresnel_lab_" + name, name + ".h"});
  headers.push_back({"fresnel_lab_energy", "energy.h"});
  headers.push_back({"fresnel_lab_energy_dielectric", "dielectric.h"});
  const Header half{"fresnel_lab_dfg_filament", "filament.h"};
  const std::string src = dir.file("tables.c", program(headers, half));
  // Two headers and nothing using them: no unused-variable warning either.
  const std::string unused =
      dir.file("unused.c",
               "#include \"dfg.h\"\n#include \"energy.h\"\nint fl_unused(void);\n"
               "int fl_unused(void) { return 0; }\n");
  const std::string flags = " -Wall -Wextra -pedantic -Werror -I '" + d + "' ";
  std::string outputs[2];
  for (int cxx = 0; cxx < 2; ++cxx) {
    const std::string cc = cxx ? "c++ -std=c++17 -x c++" : "cc -std=c99";
    const auto u = test::run_command(cc + flags + "-c '" + unused + "' -o '" + d + "unused.o'");
    EXPECT_EQ(u.status, 0) << cc << "\n" << u.err;
    const auto c = test::run_command(cc + flags + "'" + src + "' -o '" + d + "tables'");
    ASSERT_EQ(c.status, 0) << cc << "\n" << c.err;
    const auto run = test::run_command("'" + d + "tables'");
    ASSERT_EQ(run.status, 0);
    outputs[cxx] = run.out;
  }
  EXPECT_EQ(outputs[0], outputs[1]);

  // The printed texel 0 of every header against the first row of its table's CSV.
  std::map<std::string, std::vector<double>> want;
  const auto dfg = first_row(d + "dfg.csv"), moments = first_row(d + "moments.csv"),
             ltc = first_row(d + "ltc.csv"), energy = first_row(d + "energy.csv"),
             dielectric = first_row(d + "dielectric.csv");
  auto put = [&](const std::string& symbol, size_t k, const std::string& value) {
    auto& v = want[symbol];
    if (v.size() <= k) v.resize(k + 1, NAN);
    v[k] = std::stod(value);
  };
  size_t ltc_2_terms = 0;  // the sphere form factor follows them in ltc_2
  for (const auto& t : fresnel::kTermRegistry) {
    const std::string dfg_suffix = texture_suffix(t.dfg.texture, dfg_textures),
                      ltc_suffix = texture_suffix(t.ltc.texture, ltc_textures),
                      ltc_texture = t.ltc.texture;
    put("fresnel_lab_dfg" + dfg_suffix, component(t.dfg.component), dfg.at(t.dfg.channel));
    put("my_dfg" + dfg_suffix, component(t.dfg.component), dfg.at(t.dfg.channel));
    put("fresnel_lab_ltc_moments" + ltc_suffix, component(t.ltc.component),
        moments.at(t.ltc.channel));
    put("fresnel_lab_" + ltc_texture, component(t.ltc.component), ltc.at(t.ltc.channel));
    ltc_2_terms += ltc_texture == "ltc_2";
  }
  put("fresnel_lab_ltc_2", ltc_2_terms, ltc.at("sphere_form_factor"));
  const char* matrix[] = {"inv_m00", "inv_m20", "inv_m02", "inv_m22"};
  for (size_t k = 0; k < 4; ++k) put("fresnel_lab_ltc_1", k, ltc.at(matrix[k]));
  put("fresnel_lab_energy", 0, energy.at("e"));
  put("fresnel_lab_energy", 1, energy.at("e_avg"));
  const char* dielectric_channels[] = {"e", "e_avg", "e_inside", "e_avg_inside"};
  for (size_t k = 0; k < 4; ++k)
    put("fresnel_lab_energy_dielectric", k, dielectric.at(dielectric_channels[k]));

  std::istringstream lines(outputs[0]);
  size_t checked = 0;
  for (std::string name; lines >> name;) {
    int size = 0, channels = 0;
    lines >> size >> channels;
    // The dielectric table's atlas: 2 × 2 tiles of 4².
    EXPECT_EQ(size, name == "fresnel_lab_energy_dielectric" ? 8 : 4) << name;
    if (name == half.symbol) {
      unsigned bits = 0;
      lines >> bits;
      EXPECT_EQ(channels, 3);
      continue;
    }
    ASSERT_EQ(want.count(name), 1u) << name;
    ASSERT_EQ(static_cast<size_t>(channels), want[name].size()) << name;
    for (int c = 0; c < channels; ++c) {
      double v = 0;
      lines >> v;
      const double w = want[name][c];
      EXPECT_NEAR(v, w, 1e-6 * std::abs(w) + 1e-12) << name << " channel " << c;
      ++checked;
    }
  }
  EXPECT_EQ(want.size(), headers.size());
  EXPECT_GE(checked, 30u);
}

bool have_glslang() {
  return test::run_command(
             "command -v glslangValidator >/dev/null && command -v spirv-val >/dev/null")
             .status == 0;
}

// glslangValidator on a standalone fragment shader (GLSL, or HLSL through its front end with entry
// point main), then spirv-val: empty when both pass, else their output.
std::string compile_fragment(const std::string& source, bool hlsl) {
  test::TempDir dir;
  const std::string src = dir.file(hlsl ? "s.hlsl" : "s.frag", source);
  const auto c = test::run_command(std::string("glslangValidator -V -S frag ") +
                                   (hlsl ? "-D -e main " : "") + "'" + src + "' -o '" + dir.path() +
                                   "/s.spv' && spirv-val '" + dir.path() + "/s.spv'");
  return c.status == 0 ? "" : c.out + c.err;
}

TEST(ShippingCli, StandaloneShadersCompileAndValidate) {
  ASSERT_TRUE(have_glslang()) << "glslang-tools and spirv-tools (scripts/setup.sh)";
  int compiled = 0;
  for (const char* model : {"schlick", "f82", "gulbrandsen", "basis4"})
    for (const char* lighting : {"punctual", "ibl", "area"})
      for (const char* lang : {"glsl", "hlsl"}) {
        const std::string what = std::string(model) + " " + lighting + " " + lang;
        const std::string args =
            std::string(" -q shader ") + model + " --lighting " + lighting + " --lang " + lang;
        const auto include = test::run_command(test::cli() + args);
        const auto standalone = test::run_command(test::cli() + args + " --standalone");
        ASSERT_EQ(standalone.status, 0) << what << ": " << standalone.err;
        ASSERT_EQ(include.status, 0) << what << ": " << include.err;
        const bool hlsl = std::string(lang) == "hlsl";
        // The include names what it was checked with and has no #version line of its own.
        EXPECT_EQ(include.out.find("\n#version"), std::string::npos) << what;
        EXPECT_NE(include.out.find(hlsl ? "HLSL pixel shader" : "`#version 450 core`"),
                  std::string::npos)
            << what;
        EXPECT_EQ(standalone.out.rfind(hlsl ? "// Generated by" : "#version 450 core\n", 0), 0u)
            << what;
        EXPECT_NE(standalone.out.find(include.out.substr(include.out.find("\n// Checked with"))),
                  std::string::npos)
            << what << ": the standalone shader holds the include's code";
        const std::string log = compile_fragment(standalone.out, hlsl);
        EXPECT_EQ(log, "") << what << "\n" << standalone.out;
        compiled += log.empty();
      }
  EXPECT_EQ(compiled, 4 * 3 * 2);
}

// The scene shaders of `plan --shader --standalone`: a scene under ibl and area (one function per
// lighting, both tables) and one under punctual lights.
TEST(ShippingCli, PlanStandaloneShadersCompileAndValidate) {
  ASSERT_TRUE(have_glslang());
  for (const char* scene : {"scene_metals", "scene_punctual"})
    for (const char* lang : {"glsl", "hlsl"}) {
      const auto r = test::run_command(test::cli() + " -q plan '" FL_EXAMPLES_DIR "/" + scene +
                                       ".yaml' --shader --standalone --lang " + lang);
      ASSERT_EQ(r.status, 0) << scene << ": " << r.err;
      EXPECT_NE(r.out.find("// Plan "), std::string::npos) << scene;
      EXPECT_EQ(compile_fragment(r.out, std::string(lang) == "hlsl"), "")
          << scene << " " << lang << "\n"
          << r.out;
    }
}

// The number after `#define NAME ` in `text` (-1 when absent).
double defined(const std::string& text, const std::string& name) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex("#define " + name + " ([0-9.]+)\n"))) return -1;
  return std::stod(m[1]);
}

// The LTC size a shader maps its uv with is the size of the table `lut` wrote, given (32) or by
// default (both commands' defaults agree); no other size appears in the code.
TEST(ShippingCli, ShaderSizeIsTheTableSize) {
  test::TempDir dir;
  const std::string d = dir.path() + "/";
  auto r = test::run_command(lut("ltc-moments --size 32 --samples 256 --out '" + d + "m.h'"));
  ASSERT_EQ(r.status, 0) << r.err;
  const double table = defined(test::read_text_file(d + "m.h"), "FRESNEL_LAB_LTC_MOMENTS_SIZE");
  EXPECT_EQ(table, 32);
  r = test::run_command(test::cli() + " -q shader f82 --lighting area --size 32");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(defined(r.out, "FRESNEL_LAB_LTC_SIZE"), table);
  EXPECT_FALSE(std::regex_search(r.out, std::regex(R"(\b64\b)"))) << r.out;

  r = test::run_command(lut("energy --samples 256 --out '" + d + "e.h'"));
  ASSERT_EQ(r.status, 0) << r.err;
  const double default_table = defined(test::read_text_file(d + "e.h"), "FRESNEL_LAB_ENERGY_SIZE");
  r = test::run_command(test::cli() + " -q shader basis4 --lighting area");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(defined(r.out, "FRESNEL_LAB_LTC_SIZE"), default_table);
  EXPECT_GT(default_table, 0);
}

TEST(ShippingCli, BadRequestsExitTwo) {
  test::TempDir dir;
  for (const std::string args :
       {" shader f82 --lighting area --size 1", " shader f82 --harness --standalone",
        " shader f82 --lang hlsl --harness", " lut dfg --size 4 --symbol 9lives --out x.h",
        " lut dfg --size 4 --symbol good --out x.csv", " lut energy --size 4 --out x.inc",
        " lut energy --dielectric --size 4 --slices 5 --out x.csv",
        " lut energy --slices 4 --out x.csv", " plan x.yaml --shader --size 0"}) {
    const auto r = test::run_command("cd '" + dir.path() + "' && " + test::cli() + args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
  }
}

}  // namespace
}  // namespace fl
