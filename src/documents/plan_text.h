#pragma once
// The words and numbers the plan's documents share.
#include <optional>
#include <string>
#include <vector>

#include "analysis/plan/plan.h"

// Shared by the plan's documents (plan_report.cpp, plan_json.cpp).
namespace fl::documents::plan_text {

inline constexpr int kParamDecimals = analysis::kPlanParamDecimals, kErrorDecimals = 3,
                     kCostDecimals = 2;

std::vector<std::string> lighting_list(const analysis::Scene& s);
std::string join(const std::vector<std::string>& v, const std::string& sep);
double error_under(const analysis::PlanChoice& c, analysis::Lighting l);
// How the engine shades the choice under l: "tables", the named approximation, or, for a mirror
// (every roughness 0), the model at n·v with no table.
std::string served(const analysis::PlanChoice& c, analysis::Lighting l);
std::string error_name(const analysis::PlanChoice& c);
std::string gpu_text(const std::optional<int>& c);  // a GPU cost, or "unmeasured"
std::vector<std::string> channel_list(const std::vector<analysis::PlanLut>& luts);
std::string params_text(const analysis::PlanChoice& m);  // "f0_r 0.9, ..."

}  // namespace fl::documents::plan_text
