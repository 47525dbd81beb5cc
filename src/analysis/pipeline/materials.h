#pragma once
// The materials a command works on: catalog names, database pages, page globs and files
// (spectral::expand_materials), or the whole catalog when none is named, loaded under a policy.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/pipeline/context.h"

namespace fl::analysis {

// The share of the visible range (weighted by the illuminant × ȳ) a material's data must cover
// by default: below it, most of what a preset or table shows would be extrapolated.
constexpr double kDefaultMinCoverage = 0.99;

struct LoadPolicy {
  // Coverage::both below this: an InputError for a material named explicitly (not matched by a
  // glob) unless skip_named; a glob's page is skipped with the reason.
  double min_coverage = kDefaultMinCoverage;
  // A page matched by a glob that cannot be read is skipped with its reason unless strict. A
  // material named explicitly that cannot be read or is below min_coverage is an InputError
  // unless skip_named (then skipped with its reason, as a glob's page).
  bool strict = false;
  bool skip_named = false;
  std::optional<spectral::MaterialClass>
      only;         // keep this class only (others skipped, with the reason)
  int threads = 0;  // 0: every hardware thread
};

struct SkippedMaterial {
  std::string spec, reason;
};

struct MaterialSet {
  std::vector<LoadedMaterial> materials;  // in argument order (a glob's pages sorted)
  std::vector<SkippedMaterial> skipped;   // in argument order, with the reason
  int requested = 0;                      // after glob expansion
};

// Loads `specs` (none: the catalog) in parallel; `progress` gets (done, total) after each.
MaterialSet load_materials(const Context& ctx, const std::vector<std::string>& specs,
                           const LoadPolicy& policy,
                           const std::function<void(int, int)>& progress = {});

}  // namespace fl::analysis
