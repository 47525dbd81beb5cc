#pragma once
// The tables `table NAME` and `reproduce` know, in report order.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/consensus/spread.h"
#include "analysis/library/rendered_library.h"
#include "analysis/lut/rendered.h"
#include "analysis/study/study.h"
#include "analysis/tables/media_tables.h"
#include "util/table.h"

namespace fl::analysis {

// What a table builder gets: the context, the loaded catalog, the blend options, and the
// per-material study (derivations and every fit), computed on first use and shared by all tables
// of a run. `study_progress` is called with (done, total) while the studies run.
class TableInputs {
 public:
  TableInputs(const Context& ctx, const std::vector<LoadedMaterial>& materials,
              const BlendOptions& blend = {}, std::function<void(int, int)> study_progress = {})
      : ctx(ctx), materials(materials), blend(blend), study_progress_(std::move(study_progress)) {}
  const Context& ctx;
  const std::vector<LoadedMaterial>& materials;
  const BlendOptions blend;
  const std::vector<MaterialStudy>& studies();
  // Every conductor page (covering the visible range) of the groups of the metals among `materials`
  // (spread.h), studied without fits.
  const PageStudies& group_pages();
  // lut-accuracy's shading points (lut_accuracy_points()).
  const std::vector<ShadingPoint>& lut_points();
  // Every database page `library --class all` keeps, rendered by the shippable pre-integrated
  // shaders (rendered_library.h).
  const RenderedLibrary& rendered_library();
  // Computes the above at once (each in parallel), for a run that builds many tables; the tables
  // may then be built concurrently.
  void prepare();

 private:
  std::function<void(int, int)> study_progress_;
  std::optional<std::vector<MaterialStudy>> studies_;
  std::optional<PageStudies> group_pages_;
  std::optional<std::vector<ShadingPoint>> lut_points_;
  std::optional<RenderedLibrary> rendered_library_;
};

struct TableSpec {
  const char* name;
  const char* summary;
  Table (*build)(TableInputs& in);
  bool in_reproduce = true;  // `reproduce` writes it (keep reproduce fast: slow tables opt out)
};

const std::vector<TableSpec>& table_specs();
const TableSpec& find_table(const std::string& name);  // InputError if unknown

}  // namespace fl::analysis
