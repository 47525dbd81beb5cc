// The consensus tables: per group, per page, per page kind, and against published presets.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "analysis/consensus/consensus.h"
#include "analysis/consensus/spread.h"
#include "analysis/study/table_notes.h"
#include "color/lab.h"
#include "spectral/pages.h"
#include "spectral/text_file.h"
#include "util/errors.h"
#include "util/quantile.h"

namespace fl::analysis {

namespace {

std::string page_name(const std::string& page) {
  return std::filesystem::path(page).filename().string();
}

std::string used_pages(const ConsensusGroup& g) {
  std::string out;
  for (const auto& p : g.pages)
    if (p.used) out += (out.empty() ? "" : " ") + page_name(p.page->material->material.source);
  return out;
}

std::string outlier_list(const ConsensusGroup& g) {
  std::string out;
  for (const auto& p : g.pages)
    if (p.outlier)
      out += (out.empty() ? "" : "; ") + page_name(p.page->material->material.source) + " (" +
             p.reason + ")";
  return out;
}

const char* kUncertaintyNote =
    "Uncertainty: basis: consensus, or single page (one bulk measurement: not a consensus, its "
    "spread unknown); pages_used bulk measurements covering the visible range; "
    "f0_de00_median/max, "
    "f82_de00_median/max: ΔE2000 of their F0 (F82) colours from the consensus'; *_lo/*_hi: each "
    "channel's range over them. Outliers: a page beyond the bulk pages' median distance + 3 × "
    "1.4826 "
    "× MAD and beyond 2 ΔE2000, in F0 or F82. Recommended: the bulk page nearest the consensus "
    "(the "
    "larger of its F0 and F82 distances), the newest within 0.05 of the nearest.";

}  // namespace

void add_uncertainty_columns(Table& t, const ConsensusSet& set) {
  t.columns.insert(t.columns.end(), {{"basis"},
                                     {"pages_used", 0},
                                     {"f0_de00_median", 3},
                                     {"f0_de00_max", 3},
                                     {"f82_de00_median", 3},
                                     {"f82_de00_max", 3}});
  for (const char* q : {"f0", "f82", "g"})
    for (const char* end : {"lo", "hi"})
      for (const char* c : {"r", "g", "b"})
        t.columns.push_back({fmt::format("{}_{}_{}", q, c, end), 6});
  t.columns.insert(t.columns.end(),
                   {{"recommended"}, {"recommended_de00", 3}, {"outliers", 0}, {"outlier_pages"}});
  for (size_t i = 0; i < set.groups.size() && i < t.rows.size(); ++i) {
    const auto& g = set.groups[i];
    auto& row = t.rows[i];
    row.insert(row.end(),
               {std::string(g.used == 1 ? "single page" : "consensus"),
                static_cast<long long>(g.used), g.f0_median, g.f0_max, g.f82_median, g.f82_max});
    for (const auto* range : {&g.f0_lo, &g.f0_hi, &g.f82_lo, &g.f82_hi, &g.g_lo, &g.g_hi})
      for (int c = 0; c < 3; ++c) row.push_back((*range)[c]);
    row.insert(row.end(), {g.recommended, g.recommended_de00, static_cast<long long>(g.outliers),
                           outlier_list(g)});
  }
  t.notes.push_back(kUncertaintyNote);
}

Table consensus_table(const Context& ctx, const ConsensusSet& set) {
  Table t;
  t.name = "consensus";
  t.title = fmt::format("Consensus presets in {}: the median of the bulk measurements",
                        ctx.settings().space);
  t.columns = {{"group"}, {"book_name"}, {"pages_all", 0}, {"pages_used", 0}, {"used"}};
  for (const char* q : {"f0", "f82"})
    for (const char* c : {"r", "g", "b"}) t.columns.push_back({fmt::format("{}_{}", q, c), 4});
  t.columns.insert(t.columns.end(), {{"f0_de00_median", 2},
                                     {"f0_de00_max", 2},
                                     {"f82_de00_median", 2},
                                     {"f82_de00_max", 2},
                                     {"outliers", 0},
                                     {"outlier_pages"},
                                     {"recommended"},
                                     {"recommended_de00", 2},
                                     {"recommended_reason"}});
  std::vector<double> medians;
  int outliers = 0, pages = 0;
  for (size_t i = 0; i < set.groups.size(); ++i) {
    const auto& g = set.groups[i];
    const auto& d = set.studies[i].derived;
    std::vector<Cell> row{g.name, g.book_name, static_cast<long long>(g.pages.size()),
                          static_cast<long long>(g.used), used_pages(g)};
    for (const auto* v : {&d.f0, &d.f82})
      for (int c = 0; c < 3; ++c) row.push_back((*v)[c]);
    row.insert(row.end(), {g.f0_median, g.f0_max, g.f82_median, g.f82_max,
                           static_cast<long long>(g.outliers), outlier_list(g),
                           page_name(g.recommended), g.recommended_de00, g.recommended_reason});
    t.rows.push_back(std::move(row));
    if (g.used >= 2) medians.push_back(g.f0_median);
    outliers += g.outliers;
    pages += static_cast<int>(g.pages.size());
  }
  t.reading = fmt::format(
      "{} groups with a bulk measurement covering the visible range; where two or more agree to "
      "a consensus, a bulk page's F0 lies a median {:.2f} ΔE2000 from it ({} groups). {} of {} "
      "pages are outliers.",
      set.groups.size(), median(medians), medians.size(), outliers, pages);
  t.notes = {
      setting_note(ctx),
      "Consensus: at each wavelength, the median over the bulk pages of the reflectance at "
      "0° and at arccos(1/7), turned back into n, k (docs/consensus.md); F0 and F82 are then "
      "the spectral procedure's, as for a page.",
      kUncertaintyNote};
  return t;
}

Table consensus_pages_table(const ConsensusSet& set) {
  Table t;
  t.name = "consensus_pages";
  t.title = "Every page's distance from its group's consensus (ΔE2000)";
  t.columns = {{"group"}, {"page"},       {"kind"},        {"kind_detail"}, {"year", 0},
               {"used"},  {"f0_de00", 3}, {"f82_de00", 3}, {"outlier"},     {"reason"}};
  for (const auto& g : set.groups)
    for (const auto& p : g.pages) {
      const auto& m = p.page->material->material;
      t.rows.push_back({g.name, m.source, std::string(spectral::to_string(m.page_class.kind)),
                        m.page_class.detail, static_cast<long long>(m.page_class.year),
                        std::string(p.used ? "yes" : "no"), p.f0_de00, p.f82_de00,
                        std::string(p.outlier ? "yes" : "no"), p.reason});
    }
  t.notes = {
      "used: a bulk measurement, part of the consensus. kind: from the database catalog's "
      "section and page name (docs/consensus.md, \"Page kinds\").",
      kUncertaintyNote};
  return t;
}

Table outlier_kinds_table(const ConsensusSet& set) {
  std::map<std::string, std::pair<long long, long long>> by_kind;  // kind → (pages, outliers)
  long long pages = 0, outliers = 0;
  for (const auto& g : set.groups)
    for (const auto& p : g.pages) {
      auto& e = by_kind[spectral::to_string(p.page->material->material.page_class.kind)];
      ++e.first, ++pages;
      e.second += p.outlier, outliers += p.outlier;
    }
  Table t;
  t.name = "outlier_kinds";
  t.title = "Outliers per page kind";
  t.columns = {{"kind"}, {"pages", 0}, {"outliers", 0}, {"share", 3}};
  for (const auto& [kind, e] : by_kind)
    t.rows.push_back({kind, e.first, e.second, static_cast<double>(e.second) / e.first});
  t.rows.push_back({std::string("all"), pages, outliers,
                    pages ? static_cast<double>(outliers) / pages : std::nan("")});
  t.reading = fmt::format(
      "{} of {} pages (metal pages covering the visible range, in groups with a "
      "consensus) are outliers.",
      outliers, pages);
  t.notes = {kUncertaintyNote};
  return t;
}

}  // namespace fl::analysis
