#pragma once
// `plan`'s output: the per-material choices, the scene-wide shader choice and the lookup tables, as
// JSON or Markdown; and the scene's shader code.
#include <string>

#include "analysis/plan/plan.h"
#include "analysis/shader/shader.h"

namespace fl::documents {

std::string plan_json(const analysis::Plan& plan);
// `costs` names where the costs came from.
std::string plan_markdown(const analysis::Plan& plan, const analysis::PlanCosts& costs);
// The chosen option's shader document (analysis::shader_document, as `doc` asks) for the scene's
// lightings: a single shader's, or each group's behind `#ifdef group_macro(group)` (groups sharing
// a model repeat it: each is its own shader variant), its comment naming the materials it serves
// with their parameters. A split is refused with --standalone (InputError).
std::string plan_shader(const analysis::Plan& plan, const analysis::ShaderDocument& doc);
// The macro selecting a group's variant in plan_shader's output: FRESNEL_GROUP_ and the group's
// name in capitals, anything but letters and digits as '_'.
std::string group_macro(const std::string& group);
// One group's shader document (the include `plan --out` writes for it); a group holding a mirror
// (roughness 0) carries the model's function at n·v too.
std::string plan_group_shader(const analysis::Plan& plan, const analysis::OptionGroup& group,
                              analysis::ShaderDocument doc);

// The include file of a group of the chosen option (`plan --out`): fresnel.EXT for a single
// shader, else fresnel_GROUP.EXT (the group's name in lower case, anything but letters and digits
// as '_').
std::string plan_include_name(const analysis::Plan& plan, const analysis::OptionGroup& group,
                              const std::string& ext);
// materials.json of `plan --out`: per material of the chosen option its group, include, model,
// parameter set and values, roughness, whether it is a mirror, the table channels it reads, its
// error as rendered and whether it meets the budget.
std::string plan_materials_json(const analysis::Plan& plan);

}  // namespace fl::documents
