#include "analysis/consensus/trusted.h"

#include <fmt/format.h>

#include <cctype>
#include <filesystem>
#include <set>

#include "spectral/pages.h"
#include "util/errors.h"
#include "util/suggest.h"

namespace fl::analysis {
namespace {

// "main/Au/nk/Johnson" → "main/Au".
std::string book_of(const std::string& page) {
  const auto first = page.find('/');
  const auto second = first == std::string::npos ? first : page.find('/', first + 1);
  return second == std::string::npos ? std::string() : page.substr(0, second);
}

StudyOptions derived_only() {
  StudyOptions o;
  o.fit = false;
  o.method_errors = false;
  return o;
}

RequestedConsensus book_consensus(const Context& ctx, const std::string& book,
                                  const std::function<void(int, int)>& progress = {}) {
  return consensus_for(ctx, {{book, {book + "/**"}}}, derived_only(), progress);
}

const PageDistance* distance_of(const ConsensusGroup& g, const std::string& page) {
  for (const auto& p : g.pages)
    if (p.page->material->material.source == page) return &p;
  return nullptr;
}

std::string why_not_trusted(const ConsensusGroup& g) {
  if (g.used < kTrustedMinPages)
    return fmt::format("{} bulk page{}, fewer than {}", g.used, g.used == 1 ? "" : "s",
                       kTrustedMinPages);
  return fmt::format(
      "its {} bulk pages disagree (F0 ΔE2000 median {:.2f}, F82 median {:.2f}; limit {:.2f})",
      g.used, g.f0_median, g.f82_median, kTrustedMaxMedianDe00);
}

// The catalog page's place against the consensus, for the reason ("" without a catalog page).
std::string catalog_note(const ShortName& s, const PageDistance* d) {
  if (s.catalog_page.empty()) return {};
  if (!d) return fmt::format("; the catalog's page {} is not among its pages", s.catalog_page);
  return fmt::format(
      "; the catalog's page {} (the talk's) is F0 {:.2f}, F82 {:.2f} ΔE2000 from it{}",
      s.catalog_page, d->f0_de00, d->f82_de00, d->outlier ? ", an outlier" : "");
}

}  // namespace

std::optional<ShortName> short_name(const spectral::DataPaths& paths, const std::string& spec) {
  std::error_code ec;
  if (spec.empty() || spectral::is_glob(spec) || spec.find('/') != std::string::npos ||
      std::filesystem::exists(spec, ec))
    return std::nullopt;
  try {
    const auto m = spectral::resolve_material(spec, paths);
    if (m.origin != spectral::Material::Origin::Catalog ||
        m.material_class != spectral::MaterialClass::Metal || m.source.rfind("main/", 0) != 0 ||
        book_of(m.source).empty())
      return std::nullopt;
    return ShortName{book_of(m.source), m.key, m.name, m.source};
  } catch (const InputError&) {
  }
  try {
    const auto r = consensus_request(paths, spec);
    return ShortName{r.name, ascii_lower(spec), spec, ""};
  } catch (const InputError&) {
    return std::nullopt;
  }
}

TrustedMaterial trusted_material(const Context& ctx, const std::string& spec, const ShortName& s,
                                 const std::function<void(int, int)>& progress) {
  const auto c = book_consensus(ctx, s.book, progress);
  const auto& g = c.set.groups.front();
  TrustedMaterial t;
  t.consensus = g.used >= kTrustedMinPages && g.f0_median <= kTrustedMaxMedianDe00 &&
                g.f82_median <= kTrustedMaxMedianDe00;
  const auto* catalog = distance_of(g, s.catalog_page);
  if (catalog) t.catalog_f0_de00 = catalog->f0_de00, t.catalog_f82_de00 = catalog->f82_de00;
  if (t.consensus) {
    t.material = c.set.materials.front();
    t.reason = fmt::format(
        "{}: the consensus of {}: {} bulk pages agree (F0 ΔE2000 from it median {:.2f}, max "
        "{:.2f}; F82 median {:.2f}, max {:.2f}){}",
        spec, s.book, g.used, g.f0_median, g.f0_max, g.f82_median, g.f82_max,
        catalog_note(s, catalog));
  } else {
    for (const auto& m : c.pages.set.materials)
      if (m.material.source == g.recommended) t.material = m;
    const auto* d = distance_of(g, g.recommended);
    t.reason = fmt::format(
        "{}: {}, the recommended page of {} (F0 {:.2f}, F82 {:.2f} ΔE2000 from the consensus): "
        "the consensus is not used, {}{}",
        spec, g.recommended, s.book, d ? d->f0_de00 : NAN, d ? d->f82_de00 : NAN,
        why_not_trusted(g), catalog_note(s, catalog));
  }
  auto& m = t.material.material;
  m.key = s.key, m.name = s.name;
  if (s.catalog_page.empty() && !common_name(m.book_name).empty()) {
    m.key = common_name(m.book_name);  // an element symbol: the element's common name
    m.name = m.key;
    m.name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(m.name[0])));
  }
  t.material.resolved = t.reason;
  return t;
}

std::string outlier_warning(const Context& ctx, const std::string& page) {
  const std::string book = book_of(page);
  if (page.rfind("main/", 0) != 0 || book.empty()) return {};
  try {
    const auto c = book_consensus(ctx, book);
    const auto* d = distance_of(c.set.groups.front(), page);
    if (!d || !d->outlier) return {};
    return fmt::format(
        "warning: {} is an outlier of the consensus of {}: F0 {:.2f}, F82 {:.2f} ΔE2000 from it "
        "({}); `presets {}` gives the element's trusted value",
        page, book, d->f0_de00, d->f82_de00, d->reason, book.substr(5));
  } catch (const InputError&) {
    return {};  // no consensus for this book
  }
}

NamedMaterials named_materials(const Context& ctx, const std::vector<std::string>& specs,
                               const Loader& load) {
  NamedMaterials out;
  if (specs.empty()) {
    out.materials = load(specs);
    return out;
  }
  std::vector<std::string> run;
  const auto flush = [&] {
    if (run.empty()) return;
    for (auto& m : load(run)) out.materials.push_back(std::move(m));
    run.clear();
  };
  std::set<std::string> warned, trusted;
  for (const auto& spec : specs) {
    const auto s = short_name(ctx.settings().paths, spec);
    if (!s) {
      if (!spectral::is_glob(spec) && warned.insert(spec).second)
        if (auto w = outlier_warning(ctx, spec); !w.empty()) out.notes.push_back(std::move(w));
      run.push_back(spec);
      continue;
    }
    flush();
    auto t = trusted_material(ctx, spec, *s);
    out.notes.push_back(t.reason);
    if (trusted.insert(t.material.material.source).second)
      out.materials.push_back(std::move(t.material));
    else
      out.notes.push_back(spec + ": named more than once: kept once");
  }
  flush();
  return out;
}

}  // namespace fl::analysis
