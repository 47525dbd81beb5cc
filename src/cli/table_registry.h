#pragma once
// The tables `table NAME` and `reproduce` know, in report order.
#include <string>
#include <vector>

#include "analysis/table.h"
#include "cli/app.h"

namespace fl::cli {

struct TableSpec {
  const char* name;
  const char* summary;
  // Builds the table; the materials are the loaded catalog.
  analysis::Table (*build)(const analysis::Context& ctx, const std::vector<analysis::LoadedMaterial>& materials,
                           const GlobalOptions& g);
  bool in_reproduce = true;  // `reproduce` writes it (keep reproduce fast: slow tables opt out)
};

const std::vector<TableSpec>& table_specs();
const TableSpec& find_table(const std::string& name);  // InputError if unknown

}  // namespace fl::cli
