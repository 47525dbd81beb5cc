#pragma once
// `plan SCENE --out DIR`: everything an engine needs for the plan's chosen shader set, computed in
// memory before anything is written (cli writes the folder with replace_folder_atomic):
//   README.md        how the files connect: which include each material uses, the functions to
//                    call, the textures to bind and how to read them, the parameters
//   materials.json   per material: its group, model, parameter set and values, roughness, the
//                    tables it reads, its error as rendered
//   fresnel[_GROUP].glsl / .hlsl   one include per shader variant (the group's model under the
//                    scene's lightings: analysis/shader)
//   dfg.exr, dfg_2.exr, ltc_1.exr, ltc_2.exr, ...   the table textures the variants read, as `lut`
//                    writes them at 64² (jobs/lut_files)
//   reference.csv    the functions' expected values for testing a port (analysis/plan/reference.h)
//   plan.md, plan.json, pareto.svg   the plan and its options' figure (draw/plan_plot)
#include <functional>
#include <string>

#include "analysis/plan/plan.h"
#include "draw/drawing.h"
#include "io/writer.h"

namespace fl::jobs {

// The marker replace_folder_atomic leaves in a folder `plan --out` made.
inline constexpr const char* kPlanMarker = ".fresnel-lab-plan";

// Progress of the tables plan_files integrates: (table, cells done, cells in all), table being
// "DFG table" or "LTC table".
using TableProgress = std::function<void(const std::string& table, int done, int total)>;

// Paths relative to the output folder; `reference` is analysis::plan_reference's table; `font` sets
// the figure's labels. `threads` for the tables (0: every hardware thread).
io::Files plan_files(const analysis::Plan& plan, const analysis::PlanCosts& costs,
                     const Table& reference, const draw::LabelFont& font, int threads = 0,
                     const TableProgress& progress = {});

}  // namespace fl::jobs
