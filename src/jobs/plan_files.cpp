#include "jobs/plan_files.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>

#include "analysis/lut/lut_layout.h"
#include "analysis/plan/reference.h"
#include "analysis/shader/shader.h"
#include "documents/plan_report.h"
#include "documents/table_formats.h"
#include "draw/plan_plot.h"
#include "fresnel/registered_models.h"
#include "jobs/lut_files.h"

namespace fl::jobs {

using analysis::Lighting;

namespace {

// The table textures the chosen option reads, as `lut dfg` and `lut ltc` write them at the plan's
// size and storage: each as EXR and as a C header.
io::Files table_files(const analysis::Plan& p, int threads, const TableProgress& progress) {
  std::set<std::string> needed;
  bool dfg = false, ltc = false;
  for (const auto& l : p.scene_luts) {
    needed.insert(l.file);
    dfg = dfg || l.lighting == "ibl";
    ltc = ltc || l.lighting == "area";
  }
  io::Files out;
  const auto keep = [&](const io::Output& o) {
    for (const auto& [path, bytes] : o.files) {
      const std::filesystem::path file = std::filesystem::path(path).filename();
      const std::string exr = std::filesystem::path(file).replace_extension(".exr").string();
      if (needed.count(exr)) out.emplace_back(file.string(), bytes);
    }
  };
  const auto labelled = [&progress](const std::string& table) -> analysis::LutProgress {
    if (!progress) return {};
    return [&progress, table](int done, int total) { progress(table, done, total); };
  };
  const auto request = [&](const char* out) {
    LutRequest r{p.tables.size, out, analysis::kLutSamples, threads};
    r.half = p.tables.storage == analysis::TexelStorage::Half;
    r.headers = true;
    return r;
  };
  if (dfg) keep(dfg_lut(request("dfg.exr"), labelled("DFG table")));
  if (ltc) keep(ltc_lut(request("ltc.exr"), labelled("LTC table")));
  return out;
}

std::string join_text(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::string readme_shaders(const analysis::Plan& p) {
  const auto& sc = p.scene_choice();
  std::string s = fmt::format(
      "## Shaders\n\n{}\n\n| include | group | model | materials | functions |\n"
      "|---|---|---|---|---|\n",
      sc.groups.size() == 1
          ? "One shader for every material."
          : "One shader variant per group (material permutations): a material's draw compiles "
            "and runs its group's include; nothing branches inside a shader.");
  for (const auto& g : sc.groups) {
    std::vector<std::string> materials, functions;
    for (size_t k : g.materials) materials.push_back(sc.materials.at(k).material);
    for (Lighting l : p.scene.lightings())
      functions.push_back(fmt::format("`{}` ({})", analysis::shader_function_name(g.model, l),
                                      analysis::lighting_name(l)));
    s += fmt::format("| `{}`, `{}` | {} | {} | {} | {} |\n",
                     documents::plan_include_name(p, g, "glsl"),
                     documents::plan_include_name(p, g, "hlsl"), g.name,
                     fresnel::model_spec(g.model).name, join_text(materials), join_text(functions));
  }
  return s +
         "\nEach include is self-contained (its helpers, the model, the table lookups); its "
         "header comment lists the materials it serves with their parameters. The `_ibl` "
         "function returns the split-sum factor that multiplies the prefiltered environment, the "
         "`_area` function the Fresnel-weighted norm that multiplies the LTC polygon integral; "
         "per-channel parameters are `vec3` (r, g, b), in the order of the model's parameter "
         "names.\n";
}

std::string readme_tables(const analysis::Plan& p) {
  if (p.scene_luts.empty())
    return "\n## Tables\n\nNone: punctual lights evaluate the model directly.\n";
  const int n = p.tables.size;
  const bool half = p.tables.storage == analysis::TexelStorage::Half;
  std::string s =
      "\n## Tables\n\n| file | C header | lighting | channels | sampled at |\n"
      "|---|---|---|---|---|\n";
  for (const auto& l : p.scene_luts)
    s += fmt::format(
        "| `{}` | `{}` | {} | {} | uv = {}·{}/{} + 0.5/{}, bilinear, clamped |\n", l.file,
        std::filesystem::path(l.file).replace_extension(".h").string(), l.lighting,
        join_text(l.channels),
        l.lighting == "ibl" ? "(n·v, perceptual roughness)" : "(perceptual roughness, √(1 − n·v))",
        n - 1, n, n);
  return s +
         fmt::format(
             "\n{0}² texels of {1} ({2} bytes in all; {3}; worst rendered RMS ΔE2000 {4} with "
             "these tables). Each table holds its "
             "axes' ends in its edge texels, so the include maps uv as above "
             "(`FRESNEL_LAB_DFG_SIZE`, `FRESNEL_LAB_LTC_SIZE` = {0}.0). Rows run from smooth to "
             "rough. Bind `dfg.exr` to the `_ibl` function's `dfg_lut` argument and `ltc_2.exr` "
             "to the `_area` function's `ltc_2` (further textures, `dfg_2.exr`, `ltc_3.exr`, "
             "follow them in the include's argument lists); `ltc_1.exr` is the LTC matrix the "
             "area-light integral itself uses. They are `fresnel-lab lut dfg --size {0}{5} --out "
             "dfg.exr` and `fresnel-lab lut ltc --size {0}{5} --out ltc.exr`; the `.h` files hold "
             "the same texels as C arrays.\n",
             n, half ? "half floats" : "32-bit floats", p.tables.bytes,
             p.tables.forced ? "the size given by --lut-size"
                             : "the fewest bytes of 16² to 128², half or float, that keep every "
                               "material within its budget",
             documents::format_number(p.tables.worst_de00, 3), half ? " --storage half" : "");
}

std::string readme_materials(const analysis::Plan& p) {
  const auto& sc = p.scene_choice();
  std::string s =
      "\n## Materials\n\n`materials.json` holds each material's parameters (and its group, "
      "include, model, roughness, the table channels it reads and its error as rendered).\n\n"
      "| material | include | model | parameters | rendered RMS ΔE2000 | tables read |\n"
      "|---|---|---|---|---|---|\n";
  for (const auto& g : sc.groups)
    for (size_t k : g.materials) {
      const auto& m = sc.materials.at(k);
      const bool mirror = p.scene.materials.at(k).mirror();
      std::vector<std::string> tables;
      for (const auto& l : analysis::material_luts(p, k)) tables.push_back(l.file);
      s += fmt::format(
          "| {} | `{}` | {} | {} | {} | {} |\n", m.material,
          documents::plan_include_name(p, g, "glsl"), fresnel::model_spec(m.model).name,
          analysis::parameter_set_name(m.set), documents::format_number(m.error, 3),
          mirror ? "none: roughness 0 is a mirror; call `" +
                       analysis::shader_function_name(m.model, Lighting::Punctual) + "(n·v, …)`"
          : tables.empty() ? "none"
                           : join_text(tables));
    }
  return s;
}

std::string readme_reference() {
  return fmt::format(
      "\n## Testing a port\n\n`reference.csv` holds, per material and lighting, what the "
      "include's function returns from these tables with these parameters (`engine_r`, `_g`, "
      "`_b`, linear RGB), the spectral truth there (`truth_…`: the GGX lobe integrated with the "
      "measured Fresnel term) and their ΔE2000 (`de00`). Rows of `function` `fresnel_NAME` are the "
      "model at cos θ = `nov` (punctual lights, mirrors); `fresnel_NAME_ibl` and `_area` rows are "
      "the function called at (`nov`, `roughness`): the materials' roughness values and the "
      "tables' edges 0 and 1, n·v from {:g} to 1. Call your port's function at each row with the "
      "material's parameters (`materials.json`, or the row's `parameters`) and the tables "
      "uploaded as their files store them (bilinear, clamp to edge), and expect the `engine_` "
      "values within 2e-4 per channel (1e-3 if you upload 32-bit tables as half floats).\n",
      analysis::kReferenceMinNov);
}

std::string plan_readme(const analysis::Plan& p) {
  const auto& sc = p.scene_choice();
  std::string s = fmt::format(
      "# Fresnel shading for {}\n\nWritten by `fresnel-lab plan {} --out DIR`. The shader set: "
      "**{}** ({}; worst rendered RMS ΔE2000 {}, median {}, budget {}). `plan.md` says why "
      "(every option considered, its cost and the Pareto front; `plan.json` the same as data) and "
      "`pareto.svg` draws it.\n\n",
      p.scene.path, p.scene.path, sc.name,
      sc.meets_every_budget() ? "meets every material's budget"
                              : "over budget: " + join_text(sc.failing),
      documents::format_number(sc.worst_de00, 3), documents::format_number(sc.median_de00, 3),
      documents::format_number(p.scene.max_de00, 3));
  return s + readme_shaders(p) + readme_tables(p) + readme_materials(p) + readme_reference();
}

}  // namespace
io::Files plan_files(const analysis::Plan& p, const analysis::PlanCosts& costs,
                     const Table& reference, const draw::LabelFont& font, int threads,
                     const TableProgress& progress) {
  io::Files out = table_files(p, threads, progress);
  std::set<std::string> includes;
  for (const auto& g : p.scene_choice().groups) {
    if (!includes.insert(documents::plan_include_name(p, g, "glsl")).second) continue;
    for (const auto lang : {analysis::ShaderLanguage::Glsl, analysis::ShaderLanguage::Hlsl}) {
      const std::string ext = lang == analysis::ShaderLanguage::Glsl ? "glsl" : "hlsl";
      const analysis::ShaderDocument doc{
          lang,
          p.tables.size,
          false,
          fmt::format("fresnel-lab plan {} --out DIR ({})", p.scene.path,
                      documents::plan_include_name(p, g, ext)),
          {}};
      out.emplace_back(documents::plan_include_name(p, g, ext),
                       documents::plan_group_shader(p, g, doc));
    }
  }
  out.emplace_back("materials.json", documents::plan_materials_json(p));
  out.emplace_back("reference.csv", documents::to_csv(reference));
  out.emplace_back("plan.md", documents::plan_markdown(p, costs));
  out.emplace_back("plan.json", documents::plan_json(p));
  out.emplace_back("pareto.svg", draw::encode(draw::plan_plot(p), draw::FileType::Svg, font));
  out.emplace_back("README.md", plan_readme(p));
  return out;
}

}  // namespace fl::jobs
