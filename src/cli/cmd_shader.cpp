// `shader MODEL`: the model's shader function, and the table lookups of pre-integrated lighting.
#include <fmt/format.h>

#include <memory>

#include "analysis/plan/reference.h"
#include "analysis/shader/shader.h"
#include "cli/app.h"
#include "documents/table_formats.h"
#include "fresnel/registered_models.h"
#include "util/errors.h"

namespace fl::cli {

namespace {

// `--reference MATERIAL... [--roughness R...]`: the reference values instead of the shader.
struct ReferenceArgs {
  std::vector<std::string> materials;
  std::vector<double> roughness;
};

int print_reference(const GlobalOptions& g, const analysis::ShaderRequest& r,
                    const ReferenceArgs& a) {
  const auto model = fresnel::model_from_name(r.model).model;
  analysis::check_lut_size(r.size);
  const auto lighting = analysis::lighting_from_name(r.lighting);
  for (double x : a.roughness)
    if (!(x >= 0.0 && x <= 1.0))
      throw InputError(fmt::format("--roughness {} out of range (0 to 1)", x));
  const auto ctx = make_context(g);
  const auto ms = load_many(g, ctx, a.materials);
  fmt::print("{}", documents::to_csv(analysis::model_reference(
                       ctx, ms, model, lighting, a.roughness, analysis::engine_tables(r.size))));
  return 0;
}

}  // namespace

void add_shader_command(CLI::App& app, GlobalOptions& g, Runner& selected) {
  auto* sub = app.add_subcommand("shader",
                                 "a self-describing shader include for a Fresnel model, with the "
                                 "lookup-table read under ibl and area");
  auto r = std::make_shared<analysis::ShaderRequest>();
  sub->add_option("MODEL", r->model, "Fresnel model: " + fresnel::model_names())->required();
  sub->add_option("--lang", r->lang, "glsl or hlsl")->capture_default_str();
  sub->add_option("--lighting", r->lighting, "punctual, ibl (DFG table) or area (LTC moments)")
      ->capture_default_str();
  sub->add_option(
         "--size", r->size,
         "texels per axis of the tables it samples (`lut --size`; the DFG and LTC uv depend on "
         "it)")
      ->capture_default_str();
  sub->add_flag("--standalone", r->standalone,
                "a complete fragment shader: #version 450 core (GLSL), the include and an entry "
                "point calling it");
  sub->add_flag("--harness", r->harness,
                "a GLSL compute shader around the function, inputs from a uniform block (what "
                "scripts/gpu_costs.sh "
                "compiles and counts)");
  auto ref = std::make_shared<ReferenceArgs>();
  sub->add_option("--reference", ref->materials,
                  "MATERIAL...: instead of the shader, reference values for testing a port (CSV: "
                  "the function's expected RGB from the default tables with each material's "
                  "derived parameters, the spectral truth, their ΔE2000); " +
                      std::string(kMaterialsHelp));
  sub->add_option("--roughness", ref->roughness,
                  "with --reference: perceptual roughness values (default 0.2 0.4 0.6 0.8 1; the "
                  "tables' edges 0 and 1 are added)");
  sub->callback([&selected, &g, r, ref] {
    selected = [&g, r, ref] {
      if (!ref->materials.empty()) return print_reference(g, *r, *ref);
      if (!ref->roughness.empty()) throw InputError("--roughness needs --reference");
      fmt::print("{}", analysis::shader_text(*r));
      return 0;
    };
  });
}

}  // namespace fl::cli
