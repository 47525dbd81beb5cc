#pragma once
// `plan`'s output: the chosen model per scene material and the lookup tables, as JSON or Markdown.
#include <string>

#include "analysis/plan/plan.h"

namespace fl::report {

std::string plan_json(const analysis::Plan& plan);
// `cost_source` names where the costs came from (ModelCosts::source).
std::string plan_markdown(const analysis::Plan& plan, const std::string& cost_source);

}  // namespace fl::report
