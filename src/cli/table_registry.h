#pragma once
// The tables `table NAME` and `reproduce` know, in report order.
#include <optional>
#include <string>
#include <vector>

#include "analysis/study.h"
#include "analysis/table.h"
#include "cli/app.h"

namespace fl::cli {

// What a table builder gets: the context, the loaded catalog, the options, and the per-material
// study (derivations and every fit), computed on first use and shared by all tables of a run.
class TableInputs {
 public:
  TableInputs(const analysis::Context& ctx, const std::vector<analysis::LoadedMaterial>& materials,
              const GlobalOptions& g)
      : ctx(ctx), materials(materials), g(g) {}
  const analysis::Context& ctx;
  const std::vector<analysis::LoadedMaterial>& materials;
  const GlobalOptions& g;
  const std::vector<analysis::MaterialStudy>& studies();

 private:
  std::optional<std::vector<analysis::MaterialStudy>> studies_;
};

struct TableSpec {
  const char* name;
  const char* summary;
  analysis::Table (*build)(TableInputs& in);
  bool in_reproduce = true;  // `reproduce` writes it (keep reproduce fast: slow tables opt out)
};

const std::vector<TableSpec>& table_specs();
const TableSpec& find_table(const std::string& name);  // InputError if unknown

}  // namespace fl::cli
