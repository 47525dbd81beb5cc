#pragma once
// `plan`'s output: the per-material choices, the scene-wide shader choice and the lookup tables, as
// JSON or Markdown; and the scene's shader code.
#include <string>

#include "analysis/plan/plan.h"
#include "analysis/shader/shader.h"

namespace fl::report {

std::string plan_json(const analysis::Plan& plan);
// `costs` names where the costs came from.
std::string plan_markdown(const analysis::Plan& plan, const analysis::PlanCosts& costs);
// The scene-wide model's shader document for the scene's lightings (analysis::shader_document, as
// `doc` asks), its comment naming the materials it serves with their parameters.
std::string plan_shader(const analysis::Plan& plan, analysis::ShaderDocument doc);

}  // namespace fl::report
