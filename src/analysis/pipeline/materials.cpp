#include "analysis/pipeline/materials.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "spectral/pages.h"
#include "util/errors.h"
#include "util/parallel.h"
#include "util/suggest.h"

namespace fl::analysis {
namespace {

struct Slot {
  std::optional<LoadedMaterial> material;
  std::string reason;  // the error's message, when it is skipped
};

// A skip reason names the page's file relative to the database's data/ folder, so a library's
// files do not depend on where the database is.
std::string without_database_root(std::string reason, const spectral::DataPaths& paths) {
  const std::string root = paths.database + "/data/";
  if (reason.rfind(root, 0) == 0) reason.erase(0, root.size());
  return reason;
}

Slot load_request(const Context& ctx, const spectral::MaterialRequest& r, bool may_skip) {
  Slot s;
  try {
    const auto& paths = ctx.settings().paths;
    auto m = r.pattern.empty() ? spectral::resolve_material(r.spec, paths)
                               : spectral::read_database_page(r.spec, paths);
    s.material = load_material(ctx, std::move(m));
  } catch (const InputError& e) {
    if (!may_skip) throw;
    s.reason = without_database_root(e.what(), ctx.settings().paths);
  }
  return s;
}

std::string coverage_reason(const LoadedMaterial& m, double min_coverage) {
  return fmt::format("covers {:.3f} of the visible range, below --min-coverage {:g} ({})",
                     m.coverage.both, min_coverage, m.coverage.uncovered);
}

// Why the class and coverage filters leave `m` out (empty: kept); `named` (a material named
// explicitly, not by a glob) refuses instead unless the policy skips named materials.
std::string filtered_out(const LoadedMaterial& m, const LoadPolicy& p, bool named) {
  if (p.only && m.material.material_class != *p.only)
    return fmt::format("class {} (the data's), not {}",
                       spectral::to_string(m.material.material_class),
                       spectral::to_string(*p.only));
  if (m.coverage.both >= p.min_coverage) return {};
  if (named && !p.skip_named)
    throw InputError(
        m.material.file.empty() ? m.material.source : m.material.file, 0,
        coverage_reason(m, p.min_coverage) +
            " (named explicitly: lower --min-coverage, or --skip-unusable to skip it)");
  return coverage_reason(m, p.min_coverage);
}

// Adds a loaded material or its reason to be left out, in order.
void add(MaterialSet& set, LoadedMaterial m, const std::string& spec, const LoadPolicy& p,
         bool named) {
  const std::string why = filtered_out(m, p, named);
  if (why.empty())
    set.materials.push_back(std::move(m));
  else
    set.skipped.push_back({spec, why});
}

// Every material of a document gets a name of its own: the same page or file named twice (a glob
// and an explicit name) is kept once; two different materials with one name or key (Cu.csv in two
// folders) are told apart by the same numbered suffix on the later one's name and key, "_2", with
// a warning, so every format calls it the same.
void make_names_unique(MaterialSet& set) {
  std::vector<LoadedMaterial> kept;
  std::set<std::string> sources, names, keys;
  for (auto& m : set.materials) {
    auto& mat = m.material;
    if (!sources.insert(mat.file.empty() ? mat.source : mat.file).second) {
      set.skipped.push_back({mat.key, "named more than once: kept once"});
      continue;
    }
    const std::string first_name = mat.name;
    for (int n = 2; names.count(ascii_lower(mat.name)); ++n)
      mat.name = fmt::format("{}_{}", first_name, n);
    const std::string first_key = mat.key;
    for (int n = 2; keys.count(ascii_lower(mat.key)); ++n)
      mat.key = fmt::format("{}_{}", first_key, n);
    if (mat.name != first_name || mat.key != first_key)
      m.warnings.push_back(
          fmt::format("{}: another material is already named '{}': this one is "
                      "'{}' here",
                      mat.source, mat.name != first_name ? first_name : first_key,
                      mat.name != first_name ? mat.name : mat.key));
    names.insert(ascii_lower(mat.name));
    keys.insert(ascii_lower(mat.key));
    kept.push_back(std::move(m));
  }
  set.materials = std::move(kept);
}

}  // namespace

MaterialSet load_materials(const Context& ctx, const std::vector<std::string>& specs,
                           const LoadPolicy& policy,
                           const std::function<void(int, int)>& progress) {
  MaterialSet set;
  if (specs.empty()) {
    for (auto& m : load_catalog(ctx)) {
      const std::string key = m.material.key;
      add(set, std::move(m), key, policy, false);
      ++set.requested;
    }
    return set;
  }
  const auto requests = spectral::expand_materials(specs, ctx.settings().paths);
  set.requested = static_cast<int>(requests.size());
  // The page catalog is read once, under a lock: before the parallel loads rather than by the
  // first of them while the others wait (a caller running this beside other work keeps its threads
  // busy).
  if (std::any_of(requests.begin(), requests.end(),
                  [](const auto& r) { return !r.pattern.empty(); }))
    ctx.settings().paths.pages->entries();
  std::vector<Slot> slots(requests.size());
  ProgressCounter done(progress, set.requested);
  // Every request is loaded; the first error in request order is the one reported.
  parallel_for_all(
      requests.size(),
      [&](size_t i) {
        const bool glob = !requests[i].pattern.empty();
        slots[i] = load_request(ctx, requests[i], glob ? !policy.strict : policy.skip_named);
        done.add(1);
      },
      policy.threads);
  for (size_t i = 0; i < slots.size(); ++i) {
    if (slots[i].material)
      add(set, std::move(*slots[i].material), requests[i].spec, policy,
          requests[i].pattern.empty());
    else
      set.skipped.push_back({requests[i].spec, slots[i].reason});
  }
  make_names_unique(set);
  return set;
}

}  // namespace fl::analysis
