#include "analysis/consensus/consensus.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>

#include "analysis/consensus/spread.h"
#include "color/lab.h"
#include "fresnel/exact.h"
#include "spectral/pages.h"
#include "spectral/text_file.h"
#include "util/errors.h"
#include "util/parallel.h"
#include "util/quantile.h"
#include "util/suggest.h"

namespace fl::analysis {

namespace {

// κ on the circle of normal-incidence reflectance r0 at η (0 where rounding makes κ² negative).
double kappa_on_circle(double r0, double eta) {
  const double k2 = ((eta + 1) * (eta + 1) * r0 - (eta - 1) * (eta - 1)) / (1 - r0);
  return std::sqrt(std::max(k2, 0.0));
}

double grazing_residual(double r0, double r82, double eta) {
  return fresnel::fresnel_conductor(kConsensusCosGrazing, eta, kappa_on_circle(r0, eta)) - r82;
}

// Scan samples along the circle: enough that neighbouring samples bracket one root each for the
// smooth R(1/7) of metals.
constexpr int kCircleSamples = 400;
constexpr int kBisections = 100;

double bisect(double r0, double r82, double lo, double hi) {
  double f_lo = grazing_residual(r0, r82, lo);
  for (int i = 0; i < kBisections && hi - lo > 1e-15 * hi; ++i) {
    const double mid = std::sqrt(lo * hi);  // bisection in log η
    const double f_mid = grazing_residual(r0, r82, mid);
    if ((f_mid < 0) == (f_lo < 0))
      lo = mid, f_lo = f_mid;
    else
      hi = mid;
  }
  return std::sqrt(lo * hi);
}

}  // namespace

std::complex<double> invert_reflectance_pair(double r0, double r82, double eta_hint) {
  const double s = std::sqrt(r0);
  const double eta_min = (1 - s) / (1 + s), eta_max = (1 + s) / (1 - s);
  const double log_min = std::log(eta_min), step = (std::log(eta_max) - log_min) / kCircleSamples;
  const auto eta_at = [&](int i) {
    return i == 0 ? eta_min : i == kCircleSamples ? eta_max : std::exp(log_min + step * i);
  };
  const double log_hint = std::log(std::max(eta_hint, 1e-12));
  double best = eta_min, best_distance = INFINITY, nearest = eta_min, nearest_miss = INFINITY;
  double f_prev = grazing_residual(r0, r82, eta_at(0));
  for (int i = 1; i <= kCircleSamples; ++i) {
    const double f = grazing_residual(r0, r82, eta_at(i));
    if (std::abs(f) < nearest_miss) nearest_miss = std::abs(f), nearest = eta_at(i);
    if ((f < 0) != (f_prev < 0) || f == 0) {
      const double root = bisect(r0, r82, eta_at(i - 1), eta_at(i));
      const double d = std::abs(std::log(root) - log_hint);
      if (d < best_distance) best_distance = d, best = root;
    }
    f_prev = f;
  }
  const double eta = std::isfinite(best_distance) ? best : nearest;
  return {eta, kappa_on_circle(r0, eta)};
}

spectral::ComplexIorSpectrum consensus_ior(
    const std::vector<const spectral::ComplexIorSpectrum*>& pages, double eta_outside) {
  spectral::ComplexIorSpectrum out;
  if (pages.empty()) return out;
  out.grid = pages.front()->grid;
  out.ior.resize(pages.front()->ior.size());
  std::vector<double> r0(pages.size()), r82(pages.size()), eta(pages.size());
  for (size_t w = 0; w < out.ior.size(); ++w) {
    for (size_t p = 0; p < pages.size(); ++p) {
      const std::complex<double> rel = pages[p]->ior[w] / eta_outside;
      r0[p] = fresnel::fresnel_conductor(1.0, rel);
      r82[p] = fresnel::fresnel_conductor(kConsensusCosGrazing, rel);
      eta[p] = rel.real();
    }
    out.ior[w] = eta_outside *
                 invert_reflectance_pair(sample_median(r0), sample_median(r82), sample_median(eta));
  }
  return out;
}

std::string common_name(const std::string& book_name) {
  const auto open = book_name.find('('), close = book_name.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close < open) return {};
  return ascii_lower(book_name.substr(open + 1, close - open - 1));
}

ConsensusRequest consensus_request(const spectral::DataPaths& paths, const std::string& spec) {
  if (const auto eq = spec.find('='); eq != std::string::npos) {
    ConsensusRequest r{spec.substr(0, eq), {}};
    const std::string globs = spec.substr(eq + 1);
    for (const auto glob : spectral::split_fields(globs, ",")) r.globs.emplace_back(glob);
    if (r.name.empty() || r.globs.empty())
      throw InputError(fmt::format("consensus group '{}': expected NAME=GLOB[,GLOB...]", spec));
    return r;
  }
  if (spectral::is_glob(spec) || spec.find('/') != std::string::npos) return {spec, {spec}};
  const std::string want = ascii_lower(spec);
  const auto catalog = spectral::page_catalog(paths);  // kept alive for the loop
  for (const auto& [page, e] : catalog->entries())
    if (page.rfind("main/", 0) == 0 &&
        (ascii_lower(e.book) == want || common_name(e.book_name) == want))
      return {"main/" + e.book, {"main/" + e.book + "/**"}};
  throw InputError(
      fmt::format("consensus group '{}': no book of the main shelf has that symbol or name in "
                  "{}/catalog-nk.yml",
                  spec, paths.database));
}

std::vector<GroupPages> page_groups(const std::vector<MaterialStudy>& pages) {
  std::map<std::string, std::vector<const MaterialStudy*>> by_group;
  for (const auto& s : pages) {
    const std::string g = spread_group_of(*s.material);
    if (!g.empty()) by_group[g].push_back(&s);
  }
  std::vector<GroupPages> out;
  for (auto& [name, group] : by_group) out.push_back({name, std::move(group)});
  return out;
}

namespace {

// "gold" → "Gold".
std::string display_name(std::string name) {
  if (!name.empty()) name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
  return name;
}

std::string page_name(const std::string& page) {
  return std::filesystem::path(page).filename().string();
}

bool used_for_consensus(const MaterialStudy& s) {
  return s.material->material.bulk_measurement;
}

// The consensus of one group's bulk pages as a material.
LoadedMaterial consensus_material(const Context& ctx, const GroupPages& g) {
  std::vector<const spectral::ComplexIorSpectrum*> iors;
  std::string names;
  LoadedMaterial out;
  out.coverage.both = 1.0;
  for (const auto* s : g.pages) {
    if (!used_for_consensus(*s)) continue;
    iors.push_back(&s->material->ior);
    names += (names.empty() ? "" : ", ") + page_name(s->material->material.source);
    out.coverage.both = std::min(out.coverage.both, s->material->coverage.both);
    out.coverage.n = std::min(out.coverage.n, s->material->coverage.n);
    out.coverage.k = std::min(out.coverage.k, s->material->coverage.k);
    if (s->material->coverage.extrapolated) {
      out.coverage.extrapolated = true;
      out.coverage.uncovered += (out.coverage.uncovered.empty() ? "" : "; ") +
                                page_name(s->material->material.source) + ": " +
                                s->material->coverage.uncovered;
    }
  }
  out.ior = consensus_ior(iors, ctx.settings().eta_outside);
  auto& m = out.material;
  m.origin = spectral::Material::Origin::Consensus;
  m.source = g.name + "/consensus";
  m.book_name = g.pages.front()->material->material.book_name;
  // An element's consensus carries the element's common name ("Gold", key "gold").
  const std::string common = g.name.rfind("main/", 0) == 0 ? common_name(m.book_name) : "";
  m.key = common.empty() ? m.source : common;
  m.name = common.empty() ? m.source : display_name(common);
  m.section = iors.size() == 1 ? "a single bulk page, not a consensus"
                               : fmt::format("consensus of {} bulk pages", iors.size());
  m.reference = "per-wavelength median of R(0°) and R(arccos 1/7) over " + names;
  m.material_class = spectral::MaterialClass::Metal;
  return out;
}

struct Spread {
  double median = 0, max = 0, limit = 0;
};
// The consensus decides with these (outliers, whether the pages agree): estimators, on the sample
// median (util/quantile.h), not the reports' nearest rank.
Spread spread_of(const std::vector<double>& used) {
  Spread s;
  s.median = sample_median(used);
  s.max = used.empty() ? 0.0 : *std::max_element(used.begin(), used.end());
  std::vector<double> dev;
  for (const double d : used) dev.push_back(std::abs(d - s.median));
  s.limit = std::max(s.median + kOutlierMads * kMadToSigma * sample_median(dev), kOutlierMinDe00);
  return s;
}

std::string kind_text(const spectral::Material& m) {
  const auto& c = m.page_class;
  return std::string(spectral::to_string(c.kind)) + (c.detail.empty() ? "" : " " + c.detail);
}

void flag_outliers(ConsensusGroup& g) {
  for (auto& p : g.pages) {
    std::vector<std::string> why;
    if (p.f0_de00 > g.f0_limit)
      why.push_back(
          fmt::format("F0 {:.2f} ΔE2000 from the consensus (limit {:.2f})", p.f0_de00, g.f0_limit));
    if (p.f82_de00 > g.f82_limit)
      why.push_back(fmt::format("F82 {:.2f} (limit {:.2f})", p.f82_de00, g.f82_limit));
    p.outlier = !why.empty();
    if (!p.outlier) continue;
    ++g.outliers;
    p.reason = kind_text(p.page->material->material) + ": " + why.front() +
               (why.size() > 1 ? "; " + why.back() : "");
  }
}

void recommend(ConsensusGroup& g) {
  const PageDistance* best = nullptr;
  const auto far = [](const PageDistance& p) { return std::max(p.f0_de00, p.f82_de00); };
  for (const auto& p : g.pages)
    if (p.used && (!best || far(p) < far(*best))) best = &p;
  if (!best) return;
  const PageDistance* pick = best;
  const PageDistance* runner_up = nullptr;
  for (const auto& p : g.pages) {
    if (!p.used || &p == best) continue;
    if (far(p) <= far(*best) + kRecommendTieDe00 &&
        p.page->material->material.page_class.year > pick->page->material->material.page_class.year)
      pick = &p;
    if (!runner_up || far(p) < far(*runner_up)) runner_up = &p;
  }
  g.recommended = pick->page->material->material.source;
  g.recommended_de00 = far(*pick);
  g.recommended_reason =
      fmt::format("nearest the consensus among {} bulk page{} (F0 {:.2f}, F82 {:.2f} ΔE2000)",
                  g.used, g.used == 1 ? "" : "s", pick->f0_de00, pick->f82_de00);
  if (pick != best)
    g.recommended_reason +=
        fmt::format("; within {:.2f} of {} ({:.2f}) and newer ({})", kRecommendTieDe00,
                    page_name(best->page->material->material.source), far(*best),
                    pick->page->material->material.page_class.year);
  else if (runner_up)
    g.recommended_reason +=
        fmt::format("; next {} at {:.2f}", page_name(runner_up->page->material->material.source),
                    far(*runner_up));
}

void channel_range(color::Rgb& lo, color::Rgb& hi, const color::Rgb& v, bool first) {
  for (int c = 0; c < 3; ++c) {
    lo[c] = first ? v[c] : std::min(lo[c], v[c]);
    hi[c] = first ? v[c] : std::max(hi[c], v[c]);
  }
}

ConsensusGroup summarize(const Context& ctx, const GroupPages& in, const MaterialStudy& consensus) {
  ConsensusGroup g;
  g.name = in.name;
  g.book_name = consensus.material->material.book_name;
  const auto f0 = ctx.rgb_to_lab(consensus.derived.f0), f82 = ctx.rgb_to_lab(consensus.derived.f82);
  std::vector<double> used_f0, used_f82;
  for (const auto* s : in.pages) {
    PageDistance p{s,
                   color::ciede2000<double>(ctx.rgb_to_lab(s->derived.f0), f0),
                   color::ciede2000<double>(ctx.rgb_to_lab(s->derived.f82), f82),
                   used_for_consensus(*s),
                   false,
                   {}};
    if (p.used) {
      used_f0.push_back(p.f0_de00), used_f82.push_back(p.f82_de00);
      const bool first = g.used++ == 0;
      channel_range(g.f0_lo, g.f0_hi, s->derived.f0, first);
      channel_range(g.f82_lo, g.f82_hi, s->derived.f82, first);
      channel_range(g.g_lo, g.g_hi, s->derived.g_refl_eta, first);
    }
    g.pages.push_back(std::move(p));
  }
  const auto s0 = spread_of(used_f0), s82 = spread_of(used_f82);
  g.f0_median = s0.median, g.f0_max = s0.max, g.f0_limit = s0.limit;
  g.f82_median = s82.median, g.f82_max = s82.max, g.f82_limit = s82.limit;
  flag_outliers(g);
  recommend(g);
  return g;
}

}  // namespace

ConsensusSet build_consensus(const Context& ctx, const std::vector<GroupPages>& groups,
                             const StudyOptions& options,
                             const std::function<void(int, int)>& progress) {
  ConsensusSet set;
  std::vector<const GroupPages*> kept;
  for (const auto& g : groups)
    if (std::any_of(g.pages.begin(), g.pages.end(),
                    [](const MaterialStudy* s) { return used_for_consensus(*s); }))
      kept.push_back(&g);
  set.materials.resize(kept.size());
  parallel_for_all(kept.size(),
                   [&](size_t i) { set.materials[i] = consensus_material(ctx, *kept[i]); });
  set.studies = study_materials(ctx, set.materials, options, progress);
  for (size_t i = 0; i < kept.size(); ++i) {
    set.groups.push_back(summarize(ctx, *kept[i], set.studies[i]));
    const auto& g = set.groups.back();
    set.materials[i].consensus =
        ConsensusBasis{g.used,  g.f0_median, g.f0_max, g.f82_median, g.f82_max,
                       g.f0_lo, g.f0_hi,     g.f82_lo, g.f82_hi};
  }
  return set;
}

RequestedConsensus consensus_for(const Context& ctx, const std::vector<ConsensusRequest>& requests,
                                 const StudyOptions& options,
                                 const std::function<void(int, int)>& progress) {
  RequestedConsensus out;
  std::vector<std::string> globs;
  for (const auto& r : requests) globs.insert(globs.end(), r.globs.begin(), r.globs.end());
  out.pages = study_pages(ctx, globs, progress);
  std::vector<GroupPages> groups;
  for (const auto& r : requests) {
    GroupPages g{r.name, {}};
    for (const auto& s : out.pages.studies)
      if (std::any_of(r.globs.begin(), r.globs.end(), [&](const std::string& glob) {
            return spectral::glob_match(glob, s.material->material.source);
          }))
        g.pages.push_back(&s);
    if (g.pages.empty())
      throw InputError(fmt::format(
          "consensus group '{}': no metal page covering the visible range matches", r.name));
    if (std::none_of(g.pages.begin(), g.pages.end(),
                     [](const MaterialStudy* s) { return used_for_consensus(*s); }))
      throw InputError(
          fmt::format("consensus group '{}': none of its {} metal pages is a bulk measurement",
                      r.name, g.pages.size()));
    groups.push_back(std::move(g));
  }
  out.set = build_consensus(ctx, groups, options);
  return out;
}

const PageDistance* find_distance(const ConsensusSet& set, const MaterialStudy& page) {
  for (const auto& g : set.groups)
    for (const auto& p : g.pages)
      if (p.page->material == page.material) return &p;
  return nullptr;
}

}  // namespace fl::analysis
