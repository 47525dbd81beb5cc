// Shader code (analysis/shader): every model × lighting × language compiles with glslangValidator
// (Debian glslang-tools; HLSL through its HLSL front end) and its SPIR-V validates with spirv-val
// (spirv-tools); the GLSL computes what the C++ kernels compute: with constant inputs,
// `spirv-opt -O` folds the whole function into one constant (its folder evaluates the arithmetic
// and the GLSL.std.450 instructions in float), which is compared with the C++ model, an
// implementation written separately. The GPU-cost counter (scripts/gpu_costs.sh) and the committed
// costs are checked against shaders counted by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/lut/rendered.h"
#include "analysis/shader/shader.h"
#include "csv_reader.h"
#include "fresnel/registered_models.h"
#include "fresnel/registry.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl::analysis {
namespace {

using fresnel::ModelSpec;

// Float shader code (folded by spirv-opt in float) against the double C++ kernels: float's 24
// bits through a few dozen operations (measured 3.4e-7 over every model).
constexpr double kFoldTolerance = 2e-6;

bool have_tools() {
  return test::run_command(
             "command -v glslangValidator >/dev/null && command -v spirv-val >/dev/null && command "
             "-v spirv-opt >/dev/null && "
             "command -v spirv-dis >/dev/null")
             .status == 0;
}

struct Compiled {
  bool ok = false;
  std::string log;
  std::string optimized;  // spirv-dis of spirv-opt -O
};

// Compiles `source` (GLSL compute, or HLSL with entry point main) and validates it; with
// `optimize`, also runs spirv-opt -O, validates again and returns the disassembly.
Compiled compile(const std::string& source, bool hlsl, bool optimize) {
  test::TempDir dir;
  const std::string src = dir.file(hlsl ? "s.hlsl" : "s.comp", source);
  const std::string spv = dir.path() + "/s.spv", opt = dir.path() + "/o.spv",
                    log = dir.path() + "/glslang.log";
  const std::string front =
      hlsl ? "glslangValidator -D -V -S comp -e main " : "glslangValidator -V ";
  std::string cmd = "(" + front + "'" + src + "' -o '" + spv + "' > '" + log + "' || (cat '" + log +
                    "'; false)) && spirv-val '" + spv + "'";
  if (optimize)
    cmd += " && spirv-opt -O '" + spv + "' -o '" + opt + "' && spirv-val '" + opt +
           "' && spirv-dis '" + opt + "'";
  const auto r = test::run_command(cmd);
  return {r.status == 0, r.out + r.err, r.out};
}

std::string vec3_literal(const std::vector<double>& p, int per, int k, bool hlsl) {
  std::ostringstream s;
  s.precision(9);
  s << (hlsl ? "float3(" : "vec3(") << p[k] << ", " << p[per + k] << ", " << p[2 * per + k] << ")";
  return s.str();
}

// The model's parameters as literal arguments, in the function's order.
std::string argument_literals(const ModelSpec& s, const std::vector<double>& p, bool hlsl) {
  std::string out;
  const int per = s.per_channel();
  for (int k = 0; k < per; ++k) out += ", " + vec3_literal(p, per, k, hlsl);
  for (size_t k = 0; k < s.shared_params.size(); ++k) {
    std::ostringstream v;
    v.precision(9);
    v << std::showpoint << p[3 * per + k];
    out += ", " + v.str();
  }
  return out;
}

// A compute shader storing each of `calls` (expressions of the emitted functions) to o.rgb[k].
std::string glsl_program(const std::string& code, const std::vector<std::string>& calls,
                         bool with_texture) {
  std::string out =
      "#version 450\nlayout(local_size_x = 1) in;\nlayout(std430, binding = 1) buffer Outputs { "
      "vec3 rgb[" +
      std::to_string(calls.size()) + "]; } o;\n" +
      (with_texture
           ? "layout(binding = 2) uniform sampler2D lut;\nlayout(binding = 3) uniform sampler2D "
             "lut_2;\n"
           : "") +
      code + "\nvoid main() {\n";
  for (size_t k = 0; k < calls.size(); ++k)
    out += "  o.rgb[" + std::to_string(k) + "] = " + calls[k] + ";\n";
  return out + "}\n";
}

TEST(Shader, EveryModelLightingAndLanguageCompilesAndValidates) {
  ASSERT_TRUE(have_tools()) << "glslangValidator / spirv-tools missing: scripts/setup.sh installs "
                               "glslang-tools, spirv-tools";
  int compiled = 0;
  for (const auto& spec : fresnel::model_specs()) {
    const auto p = fresnel::example_params(spec.model);
    for (Lighting l : {Lighting::Punctual, Lighting::Ibl, Lighting::Area}) {
      const std::string fn = shader_function_name(spec.model, l);
      for (bool hlsl : {false, true}) {
        const auto code =
            shader_code(spec.model, {l}, hlsl ? ShaderLanguage::Hlsl : ShaderLanguage::Glsl);
        std::string lookup;  // a texture per table the entry point samples, then the sampler
        for (size_t k = 0; k < shader_textures(spec.model, l).size(); ++k)
          lookup += k ? "lut_2, " : "lut, ";
        if (l != Lighting::Punctual) lookup += hlsl ? "lut_sampler, 0.4, " : "0.4, ";
        const std::string call = fn + "(" + lookup + "0.6" + argument_literals(spec, p, hlsl) + ")";
        const std::string program =
            hlsl ? "RWStructuredBuffer<float3> o : register(u1);\nTexture2D<float4> lut : "
                   "register(t2);\nTexture2D<float4> lut_2 : register(t4);\n"
                   "SamplerState lut_sampler : register(s3);\n" +
                       code + "\n[numthreads(1, 1, 1)] void main() { o[0] = " + call + "; }\n"
                 : glsl_program(code, {call}, l != Lighting::Punctual);
        const auto c = compile(program, hlsl, false);
        EXPECT_TRUE(c.ok) << spec.name << " " << lighting_name(l) << (hlsl ? " HLSL" : " GLSL")
                          << "\n"
                          << c.log << "\n"
                          << program;
        compiled += c.ok;
      }
    }
  }
  EXPECT_EQ(compiled, static_cast<int>(fresnel::model_specs().size()) * 3 * 2);
}

// The folded constants main stores, in store order: each OpStore's value is an
// OpConstantComposite of three OpConstant floats.
bool folded_rgb(const std::string& dis, std::vector<color::Rgb>& out) {
  const size_t main_at = dis.find("%main = OpFunction");
  if (main_at == std::string::npos) return false;
  const std::string body = dis.substr(main_at);
  auto constant = [&](const std::string& cid, double& v) {
    std::smatch c;
    if (!std::regex_search(dis, c, std::regex(cid + R"( = OpConstant %float (\S+))"))) return false;
    v = std::stod(c[1]);
    return true;
  };
  const std::regex store(R"(OpStore %\S+ (%\S+))");
  for (auto it = std::sregex_iterator(body.begin(), body.end(), store);
       it != std::sregex_iterator(); ++it) {
    std::smatch m;
    const std::string id = (*it)[1];
    if (!std::regex_search(
            dis, m, std::regex(id + R"( = OpConstantComposite %v3float (%\S+) (%\S+) (%\S+))")))
      return false;
    color::Rgb rgb{};
    for (int k = 0; k < 3; ++k)
      if (!constant(m[k + 1], rgb[k])) return false;
    out.push_back(rgb);
  }
  return true;
}

std::string literal(double x) {
  std::ostringstream s;
  s.precision(9);
  s << std::showpoint << x;
  return s.str();
}

// The texels the table function of model m reads under IBL or area lights, as vec3 literals (vec4
// for a texture with a channel in A) holding the table terms' values at their components:
// "vec3(0.61, 0.12, 0.037), ".
std::string texel_literals(fresnel::Model m, Lighting l, const fresnel::TermValues& v) {
  std::string out;
  for (const auto& name : shader_textures(m, l)) {
    double rgba[4] = {};
    size_t width = 3;
    for (const auto& t : fresnel::kTermRegistry)
      if (name == (l == Lighting::Ibl ? t.dfg.texture : t.ltc.texture)) {
        const size_t c =
            std::string("rgba").find((l == Lighting::Ibl ? t.dfg.component : t.ltc.component)[0]);
        rgba[c] = v[t.term];
        width = std::max(width, c + 1);
      }
    out += "vec" + std::to_string(width) + "(" + literal(rgba[0]);
    for (size_t c = 1; c < width; ++c) out += ", " + literal(rgba[c]);
    out += "), ";
  }
  return out;
}

// Per model, one program with the model at four angles and the two table combinations from texels
// given as constants; against the C++ kernel and the rendered-error engine.
TEST(Shader, GlslComputesWhatTheKernelsCompute) {
  ASSERT_TRUE(have_tools());
  ShadingPoint point;
  point.nov = 0.35;
  point.dfg.v = {0.61, 0.12, 0.037, 0.05, -0.03, 0.02, 0.01};
  point.ltc.v = {0.73, 0.12, 0.037, 0.06, -0.025, 0.015, 0.012};
  double worst = 0;
  for (const auto& spec : fresnel::model_specs()) {
    const auto p = fresnel::example_params(spec.model);
    const std::string args = argument_literals(spec, p, false),
                      fn = "fresnel_" + std::string(spec.name);
    std::vector<std::string> calls;
    std::vector<color::Rgb> want;
    for (double c : {0.05, 0.3, 0.8, 1.0}) {
      calls.push_back(fn + "(" + literal(c) + args + ")");
      want.push_back(spec.evaluate(c, p.data(), false));
    }
    calls.push_back(fn + "_dfg(" + texel_literals(spec.model, Lighting::Ibl, point.dfg) + "0.35" +
                    args + ")");
    want.push_back(engine_shading(spec.model, p, Lighting::Ibl, point));
    calls.push_back(fn + "_ltc(" + texel_literals(spec.model, Lighting::Area, point.ltc) + "0.35" +
                    args + ")");
    want.push_back(engine_shading(spec.model, p, Lighting::Area, point));
    const auto code = shader_code(spec.model, {Lighting::Punctual, Lighting::Ibl, Lighting::Area},
                                  ShaderLanguage::Glsl);
    const auto c = compile(glsl_program(code, calls, false), false, true);
    ASSERT_TRUE(c.ok) << spec.name << "\n" << c.log;
    std::vector<color::Rgb> got;
    ASSERT_TRUE(folded_rgb(c.optimized, got)) << spec.name << ": not folded to constants\n"
                                              << c.optimized;
    ASSERT_EQ(got.size(), want.size()) << spec.name;
    for (size_t k = 0; k < want.size(); ++k)
      for (int ch = 0; ch < 3; ++ch) {
        EXPECT_NEAR(got[k][ch], want[k][ch], kFoldTolerance) << spec.name << ": " << calls[k];
        worst = std::max(worst, std::abs(got[k][ch] - want[k][ch]));
      }
  }
  std::printf("max |folded GLSL - C++ kernel| over every model: %.3g\n", worst);
}

// scripts/gpu_costs.sh's count of a SPIR-V entry point ("instructions,arithmetic,extended,texture")
// for a GLSL compute shader.
std::string gpu_cost_of(const std::string& glsl) {
  test::TempDir dir;
  const auto r = test::run_command("'" FL_SOURCE_DIR "/scripts/gpu_costs.sh' --count '" +
                                   dir.file("s.comp", glsl) + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  return r.out.substr(0, r.out.find('\n'));
}

// The counter against a shader counted by hand: o.s = pow(a, b) / a + sqrt(b) is Pow and Sqrt
// (extended) and FDiv, FAdd (arithmetic); o.rgb = c * a − texel.rgb is VectorTimesScalar, FSub
// (arithmetic), one image sample, and the sample's coordinate (CompositeConstruct) and swizzle
// (VectorShuffle): 2 + 4 + 1 + 2 = 9 instructions, the loads, access chains and stores aside.
TEST(Shader, GpuCostCounterCountsAShaderCountedByHand) {
  ASSERT_TRUE(have_tools());
  EXPECT_EQ(gpu_cost_of(R"(#version 450
layout(local_size_x = 1) in;
layout(std140, binding = 0) uniform Inputs { float a; float b; vec3 c; } u;
layout(binding = 2) uniform sampler2D lut;
layout(std430, binding = 1) buffer Outputs { vec3 rgb; float s; } o;
void main() {
  o.s = pow(u.a, u.b) / u.a + sqrt(u.b);
  o.rgb = u.c * u.a - textureLod(lut, vec2(u.a, u.b), 0.0).rgb;
}
)"),
            "9,4,2,1");
}

// Schlick counted by hand from its formula, F0 + (1 − F0)·m⁵ with m = 1 − cos θ: 1 − cos θ, m², m⁴,
// m⁵, 1 − F0, (1 − F0)·m⁵ and the sum are 7 arithmetic instructions and nothing else; under IBL,
// written from its table terms, F0·(dfg1 + dfg2) + (1 − F0)·dfg2 is an FAdd, two
// VectorTimesScalar, an FSub and an FAdd after one table sample, whose uv
// (n·v, roughness)·(N − 1)/N + ½/N is another VectorTimesScalar and FAdd: 7. The tool's emitted
// shader and the committed costs file must both show these counts; every committed row reads a
// table sample exactly under ibl and area and none under punctual light, and its parts add up to no
// more than its total.
TEST(Shader, GpuCostsAgreeWithHandCountsAndAreConsistent) {
  ASSERT_TRUE(have_tools());
  const auto harness = [](const char* lighting) {
    return test::run_command(test::cli() + " -q shader schlick --lighting " + lighting +
                             " --harness")
        .out;
  };
  EXPECT_EQ(gpu_cost_of(harness("punctual")), "7,7,0,0");
  const auto ibl = test::csv_cells(gpu_cost_of(harness("ibl")));
  ASSERT_EQ(ibl.size(), 4u);
  EXPECT_EQ(ibl[1], "7");  // arithmetic
  EXPECT_EQ(ibl[3], "1");  // texture
  const auto rows = test::csv_records(test::read_text_file(FL_SOURCE_DIR "/bench/gpu_costs.csv"),
                                      {.skip_comments = true});
  ASSERT_FALSE(rows.empty());
  for (const auto& r : rows) {
    const std::string what = r.at("model") + " " + r.at("lighting");
    const int total = std::stoi(r.at("instructions")), arithmetic = std::stoi(r.at("arithmetic")),
              extended = std::stoi(r.at("extended")), texture = std::stoi(r.at("texture"));
    const auto model = fresnel::model_from_name(r.at("model")).model;
    EXPECT_EQ(texture,
              static_cast<int>(shader_textures(model, lighting_from_name(r.at("lighting"))).size()))
        << what;
    EXPECT_LE(arithmetic + extended + texture, total) << what;
    EXPECT_GE(arithmetic, 1) << what;
    if (r.at("model") != "schlick") continue;
    if (r.at("lighting") == "punctual") {
      EXPECT_EQ(total, 7) << what;
    } else if (r.at("lighting") == "ibl") {
      EXPECT_EQ(arithmetic, 7) << what;
    }
  }
}

TEST(Shader, NamesAndBadRequests) {
  EXPECT_EQ(shader_function_name(fresnel::model_of<fresnel::models::F82>, Lighting::Ibl),
            "fresnel_f82_ibl");
  EXPECT_THROW(shader_language_from_name("metal"), fl::InputError);
  EXPECT_THROW(lighting_from_name("sun"), fl::InputError);
  EXPECT_THROW(shader_text({"f82", "hlsl", "ibl", true}), fl::InputError);
  EXPECT_THROW(shader_text({"warp", "glsl", "ibl", false}), fl::InputError);
  EXPECT_THROW(shader_text({"f82", "glsl", "area", false, 1}), fl::InputError);
  EXPECT_THROW(shader_text({"f82", "glsl", "area", true, 64, true}), fl::InputError);
}

}  // namespace
}  // namespace fl::analysis
