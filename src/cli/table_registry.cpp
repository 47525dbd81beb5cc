#include "cli/table_registry.h"

#include <fmt/format.h>

#include "analysis/tables.h"
#include "spectral/errors.h"

namespace fl::cli {

const std::vector<TableSpec>& table_specs() {
  static const std::vector<TableSpec> specs{
      {"schlick", "Schlick (spectral F0) against spectral ground truth, every catalog material",
       [](const analysis::Context& ctx, const std::vector<analysis::LoadedMaterial>& ms, const GlobalOptions&) {
         return analysis::schlick_table(ctx, ms);
       }},
  };
  return specs;
}

const TableSpec& find_table(const std::string& name) {
  std::string known;
  for (const auto& t : table_specs()) {
    if (name == t.name) return t;
    known += (known.empty() ? "" : ", ") + std::string(t.name);
  }
  throw InputError(fmt::format("unknown table '{}' (expected one of: {})", name, known));
}

}  // namespace fl::cli
