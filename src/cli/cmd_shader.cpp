// `shader MODEL`: the model's shader function, and the table lookups of pre-integrated lighting.
#include <fmt/format.h>

#include <memory>

#include "analysis/shader/shader.h"
#include "analysis/tables/tables.h"
#include "cli/app.h"

namespace fl::cli {

void add_shader_command(CLI::App& app, GlobalOptions&, Runner& selected) {
  auto* sub = app.add_subcommand("shader",
                                 "a self-describing shader include for a Fresnel model, with the "
                                 "lookup-table read under ibl and area");
  auto r = std::make_shared<analysis::ShaderRequest>();
  sub->add_option("MODEL", r->model, "Fresnel model: " + analysis::model_names())->required();
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
  sub->callback([&selected, r] {
    selected = [r] {
      fmt::print("{}", analysis::shader_text(*r));
      return 0;
    };
  });
}

}  // namespace fl::cli
