#include "analysis/pipeline/materials.h"

#include <fmt/format.h>

#include <exception>

#include "spectral/errors.h"
#include "util/parallel.h"

namespace fl::analysis {
namespace {

struct Slot {
  std::optional<LoadedMaterial> material;
  std::exception_ptr error;
  std::string reason;  // the error's message, when it may be skipped
};

Slot load_request(const Context& ctx, const spectral::MaterialRequest& r, bool may_skip) {
  Slot s;
  try {
    const auto& paths = ctx.settings().paths;
    auto m = r.pattern.empty() ? spectral::resolve_material(r.spec, paths) : spectral::read_database_page(r.spec, paths);
    s.material = load_material(ctx, std::move(m));
  } catch (const InputError& e) {
    if (!may_skip) s.error = std::current_exception();
    s.reason = e.what();
  }
  return s;
}

std::string coverage_reason(const LoadedMaterial& m, double min_coverage) {
  return fmt::format("covers {:.3f} of the visible range, below --min-coverage {:g} ({})", m.coverage.both,
                     min_coverage, m.coverage.uncovered);
}

// Applies the class and coverage filters to what loaded; `single` refuses instead of skipping.
void filter(MaterialSet& set, std::vector<LoadedMaterial> loaded, const std::vector<std::string>& specs,
            const LoadPolicy& p, bool single) {
  for (size_t i = 0; i < loaded.size(); ++i) {
    auto& m = loaded[i];
    if (p.only && m.material.material_class != *p.only) {
      set.skipped.push_back({specs[i], fmt::format("class {} (the data's), not {}",
                                                   spectral::to_string(m.material.material_class),
                                                   spectral::to_string(*p.only))});
    } else if (m.coverage.both < p.min_coverage) {
      if (single) throw InputError(m.material.source, 0, coverage_reason(m, p.min_coverage));
      set.skipped.push_back({specs[i], coverage_reason(m, p.min_coverage)});
    } else {
      set.materials.push_back(std::move(m));
    }
  }
}

}  // namespace

MaterialSet load_materials(const Context& ctx, const std::vector<std::string>& specs, const LoadPolicy& policy,
                           const std::function<void(int, int)>& progress) {
  MaterialSet set;
  if (specs.empty()) {
    std::vector<LoadedMaterial> loaded;
    std::vector<std::string> keys;
    for (auto& m : spectral::read_catalog(ctx.settings().paths)) {
      keys.push_back(m.key);
      loaded.push_back(load_material(ctx, std::move(m)));
    }
    set.requested = static_cast<int>(loaded.size());
    filter(set, std::move(loaded), keys, policy, false);
    return set;
  }
  const auto requests = spectral::expand_materials(specs, ctx.settings().paths);
  set.requested = static_cast<int>(requests.size());
  std::vector<Slot> slots(requests.size());
  ProgressCounter done(progress, set.requested);
  parallel_for(
      requests.size(),
      [&](size_t i) {
        slots[i] = load_request(ctx, requests[i], !requests[i].pattern.empty() && !policy.strict);
        done.add(1);
      },
      policy.threads);
  std::vector<LoadedMaterial> loaded;
  std::vector<std::string> names;
  for (size_t i = 0; i < slots.size(); ++i) {
    if (slots[i].error) std::rethrow_exception(slots[i].error);
    if (!slots[i].material) {
      set.skipped.push_back({requests[i].spec, slots[i].reason});
      continue;
    }
    loaded.push_back(std::move(*slots[i].material));
    names.push_back(requests[i].spec);
  }
  const bool single = requests.size() == 1 && requests.front().pattern.empty();
  filter(set, std::move(loaded), names, policy, single);
  return set;
}

}  // namespace fl::analysis
