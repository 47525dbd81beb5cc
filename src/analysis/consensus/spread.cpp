#include "analysis/consensus/spread.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "analysis/study/table_notes.h"
#include "color/lab.h"
#include "fresnel/registered_models.h"
#include "fresnel/registry.h"
#include "util/quantile.h"

namespace fl::analysis {

std::string spread_group_of(const LoadedMaterial& m) {
  if (m.material.origin != spectral::Material::Origin::Page ||
      m.material.material_class != spectral::MaterialClass::Metal ||
      m.coverage.both < kSpreadMinCoverage)
    return {};
  return spread_group(m.material.source);
}

std::string spread_group(const std::string& page) {
  const std::filesystem::path p(page);
  const std::string book = p.parent_path().parent_path().generic_string();
  if (book.empty()) return {};
  if (book.rfind("other/alloys/", 0) != 0) return book;
  const std::string name = p.filename().string();
  const auto dash = name.find('-');
  return dash == std::string::npos ? book : book + " " + name.substr(dash + 1);
}

PageStudies study_pages(const Context& ctx, const std::vector<std::string>& globs,
                        const std::function<void(int, int)>& progress) {
  PageStudies out;
  LoadPolicy policy;
  policy.min_coverage = kSpreadMinCoverage;
  policy.only = spectral::MaterialClass::Metal;
  out.set = load_materials(ctx, globs, policy, progress);
  // What the spread reads of a page: the derived F0 and F82, and Schlick's error.
  StudyOptions o;
  o.fit = false;
  o.models = {fresnel::model_of<fresnel::models::Schlick>};
  o.method_errors = false;
  out.studies = study_materials(ctx, out.set.materials, o);
  return out;
}

std::vector<std::string> group_globs(const std::vector<LoadedMaterial>& materials) {
  std::vector<std::string> globs;
  for (const auto& m : materials) {
    if (m.material.material_class != spectral::MaterialClass::Metal) continue;
    const std::string group = spread_group(m.material.source);
    if (group.empty()) continue;
    // An alloy's group is its book and composition: the book's pages with that composition.
    const auto space = group.find(' ');
    const std::string glob = space == std::string::npos
                                 ? group + "/**"
                                 : group.substr(0, space) + "/**-" + group.substr(space + 1);
    if (std::find(globs.begin(), globs.end(), glob) == globs.end()) globs.push_back(glob);
  }
  return globs;
}

namespace {

struct PageColours {
  const MaterialStudy* study;
  color::Lab f0, f82;
  double schlick_rms;
};

std::map<std::string, std::vector<PageColours>> groups_of(const Context& ctx,
                                                          const std::vector<MaterialStudy>& pages) {
  std::map<std::string, std::vector<PageColours>> groups;
  const auto schlick = fresnel::model_of<fresnel::models::Schlick>;
  for (const auto& s : pages) {
    const std::string g = spread_group_of(*s.material);
    if (g.empty()) continue;
    groups[g].push_back({&s, ctx.rgb_to_lab(s.derived.f0), ctx.rgb_to_lab(s.derived.f82),
                         s.result(schlick).derived_error.rms});
  }
  return groups;
}

const std::string& page_of(const PageColours& p) {
  return p.study->material->material.source;
}

// Largest and median pairwise ΔE2000 of one colour, and the pair at the largest.
struct PairSpread {
  double max = 0, median = 0;
  std::string pair;
};
PairSpread pair_spread(const std::vector<PageColours>& g, color::Lab PageColours::*colour) {
  PairSpread s;
  std::vector<double> all;
  for (size_t i = 0; i < g.size(); ++i)
    for (size_t j = i + 1; j < g.size(); ++j) {
      const double de = color::ciede2000<double>(g[i].*colour, g[j].*colour);
      all.push_back(de);
      if (de > s.max) s.max = de, s.pair = page_of(g[i]) + " vs " + page_of(g[j]);
    }
  s.median = median(all);
  return s;
}

std::string page_name(const std::string& page) {
  return std::filesystem::path(page).filename().string();
}

}  // namespace

namespace {

// One row of the spread table: a group's pages of one kind.
void add_spread_row(Table& t, const std::string& name, const char* kind,
                    const std::vector<PageColours>& g) {
  const auto f0 = pair_spread(g, &PageColours::f0), f82 = pair_spread(g, &PageColours::f82);
  const auto [lo, hi] = std::minmax_element(
      g.begin(), g.end(),
      [](const PageColours& a, const PageColours& b) { return a.schlick_rms < b.schlick_rms; });
  t.rows.push_back({name, std::string(kind), static_cast<long long>(g.size()), f0.max, f0.median,
                    f82.max, f82.median, lo->schlick_rms, hi->schlick_rms,
                    hi->schlick_rms - lo->schlick_rms, f0.pair, page_name(page_of(*lo)),
                    page_name(page_of(*hi))});
}

}  // namespace

Table spread_table(const Context& ctx, const std::vector<MaterialStudy>& pages) {
  Table t;
  t.name = "spread";
  t.title = "How much measurements disagree: the spread between database pages of the same metal";
  t.columns = {{"material"},           {"pages"},
               {"count", 0},           {"f0_de00_max", 3},
               {"f0_de00_median", 3},  {"f82_de00_max", 3},
               {"f82_de00_median", 3}, {"schlick_rms_min", 3},
               {"schlick_rms_max", 3}, {"schlick_rms_range", 3},
               {"f0_farthest_pair"},   {"schlick_min_page"},
               {"schlick_max_page"}};
  std::vector<double> f0_max, range;
  int visible = 0;
  for (const auto& [name, all] : groups_of(ctx, pages)) {
    std::vector<PageColours> bulk;
    for (const auto& p : all)
      if (p.study->material->material.bulk_measurement) bulk.push_back(p);
    if (bulk.size() >= 2) {
      add_spread_row(t, name, "bulk measurements", bulk);
      f0_max.push_back(std::get<double>(t.rows.back()[3]));
      range.push_back(std::get<double>(t.rows.back()[9]));
      visible += f0_max.back() > 1.0;
    }
    if (all.size() >= 2 && all.size() != bulk.size()) add_spread_row(t, name, "all pages", all);
  }
  t.reading = fmt::format(
      "{} metals have two or more bulk measurements covering the visible range. Between them the "
      "F0 colours differ "
      "by up to a median {:.2f} ΔE2000 (the largest pair per metal; {} of {} above 1, a visible "
      "difference), and "
      "Schlick's RMS error changes by a median {:.2f} with the page: the choice of measurement "
      "moves a colour more "
      "than most approximations do.",
      f0_max.size(), median(f0_max), visible, f0_max.size(), median(range));
  t.notes = {
      setting_note(ctx),
      fmt::format("Pages: conductor pages (class from the data) covering at least {:g} of the "
                  "visible range; a "
                  "metal is a database book (on the alloys shelf, a book and its composition).",
                  kSpreadMinCoverage),
      "bulk measurements: pages of kind bulk (from the database catalog's section and page name: "
      "not models, computed data, thin films, nanostructures, or measurements away from room "
      "temperature; docs/consensus.md); all pages: every page (a row only when it differs).",
      "f0_de00, f82_de00: ΔE2000 between every pair of pages' F0 (F82) colours from the spectral "
      "procedure; "
      "schlick_rms: each page's RMS ΔE2000 of Schlick against its own ground truth (the schlick "
      "table's "
      "measure)."};
  return t;
}

namespace {

// The sentence explaining one miss: where the talk's value lies against the pages' range.
std::string miss_sentence(const std::string& material, double ours, double talk, double lo,
                          double hi, const std::string& lo_page, const std::string& hi_page,
                          size_t pages) {
  const double gap = talk < lo ? lo - talk : talk > hi ? talk - hi : 0.0;
  const std::string where =
      gap == 0.0
          ? fmt::format("lies within the {:.3f}-{:.3f} that the {} pages give", lo, hi, pages)
          : fmt::format("lies {:.3f} {} the {} of the {} pages ({}, {:.3f})", gap,
                        talk < lo ? "below" : "above", talk < lo ? "lowest" : "highest", pages,
                        talk < lo ? lo_page : hi_page, talk < lo ? lo : hi);
  return fmt::format(
      "{}: ours {:.3f}, the talk's {:.3f}; the talk's value {}; the pages span {:.3f}, so the miss "
      "is "
      "{:.0f}% of what the choice of measurement alone changes.",
      material, ours, talk, where, hi - lo, 100.0 * std::abs(ours - talk) / (hi - lo));
}

struct TalkCounts {
  int misses = 0;
  std::vector<std::string> sentences;
};

void add_talk_row(Table& t, const Context& ctx, const LoadedMaterial& m,
                  const std::vector<PageColours>& g, TalkCounts& counts) {
  const auto truth = ground_truth_curve(ctx, m.ior, ctx.settings().eta_outside);
  const auto schlick = fresnel::evaluate_curve(fresnel::model_of<fresnel::models::Schlick>,
                                               {truth.front().r, truth.front().g, truth.front().b},
                                               ctx.cos_thetas());
  const double ours = curve_error(ctx, truth, schlick).rms, talk = m.material.talk_schlick_rms_de00;
  const bool miss = std::abs(ours - talk) > kTalkMissTolerance;
  counts.misses += miss;
  std::vector<Cell> row{m.material.name,
                        m.material.source,
                        ours,
                        talk,
                        ours - talk,
                        std::string(miss ? "yes" : "no"),
                        static_cast<long long>(g.size())};
  if (g.size() < 2) {
    row.insert(row.end(), {std::nan(""), std::nan(""), std::string("n/a"), std::string(),
                           std::nan(""), std::nan("")});
    if (miss)
      counts.sentences.push_back(
          fmt::format("{}: ours {:.3f}, the talk's {:.3f}; no other page to compare.",
                      m.material.name, ours, talk));
    t.rows.push_back(std::move(row));
    return;
  }
  const auto by_rms = [](const PageColours& a, const PageColours& b) {
    return a.schlick_rms < b.schlick_rms;
  };
  const auto [lo, hi] = std::minmax_element(g.begin(), g.end(), by_rms);
  const auto nearest =
      std::min_element(g.begin(), g.end(), [&](const PageColours& a, const PageColours& b) {
        return std::abs(a.schlick_rms - talk) < std::abs(b.schlick_rms - talk);
      });
  const bool within = talk >= lo->schlick_rms && talk <= hi->schlick_rms;
  row.insert(row.end(), {lo->schlick_rms, hi->schlick_rms, std::string(within ? "yes" : "no"),
                         page_of(*nearest), nearest->schlick_rms,
                         color::ciede2000<double>(ctx.rgb_to_lab(truth.front()), nearest->f0)});
  if (miss)
    counts.sentences.push_back(miss_sentence(m.material.name, ours, talk, lo->schlick_rms,
                                             hi->schlick_rms, page_of(*lo), page_of(*hi),
                                             g.size()));
  t.rows.push_back(std::move(row));
}

}  // namespace

Table talk_misses_table(const Context& ctx, const std::vector<LoadedMaterial>& catalog,
                        const std::vector<MaterialStudy>& pages) {
  Table t;
  t.name = "talk_spread";
  t.title =
      "The talk's Schlick values against the spread of the database's pages (RMS ΔE2000, metals)";
  t.columns = {{"material"},
               {"source"},
               {"ours", 3},
               {"talk", 3},
               {"difference", 3},
               {"misses"},
               {"pages", 0},
               {"pages_min", 3},
               {"pages_max", 3},
               {"talk_within"},
               {"nearest_page"},
               {"nearest_rms", 3},
               {"f0_de00_to_nearest", 3}};
  const auto groups = groups_of(ctx, pages);
  TalkCounts counts;
  for (const auto& m : catalog) {
    if (m.material.material_class != spectral::MaterialClass::Metal ||
        m.material.talk_schlick_rms_de00 < 0)
      continue;
    const auto it = groups.find(spread_group(m.material.source));
    add_talk_row(t, ctx, m, it == groups.end() ? std::vector<PageColours>{} : it->second, counts);
  }
  t.reading = fmt::format("{} of the talk's metal values {} missed by more than {:.2f}.",
                          counts.misses, counts.misses == 1 ? "is" : "are", kTalkMissTolerance);
  for (const auto& sentence : counts.sentences) t.reading += " " + sentence;
  t.notes = {setting_note(ctx),
             "ours: Schlick (spectral F0) against ground truth on the catalog's page, as in the "
             "schlick table; pages, "
             "pages_min, pages_max: the same over every conductor page of the metal covering the "
             "visible range (the "
             "spread table's all pages); nearest_page: the page whose error is closest to the "
             "talk's value.",
             "f0_de00_to_nearest: ΔE2000 between the catalog page's F0 and the nearest page's."};
  return t;
}

}  // namespace fl::analysis
