#include "analysis/library/library.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "analysis/consensus/spread.h"
#include "analysis/presets/preset_tables.h"
#include "analysis/study/table_notes.h"
#include "fresnel/registered_models.h"
#include "spectral/pages.h"
#include "spectral/text_file.h"

namespace fl::analysis {

namespace {

std::vector<Cell> page_row(const std::string& page, const spectral::PageEntry* entry) {
  const auto kind = spectral::classify_page(entry);
  return {page,
          spectral::book_of(page),
          entry ? entry->book_name : std::string(),
          entry ? entry->section : std::string(),
          std::string(spectral::to_string(kind.kind)),
          kind.detail};
}

}  // namespace

namespace {
// The listing shows every page, whatever it covers: coverage is one of its columns.
LoadPolicy every_page() {
  LoadPolicy p;
  p.min_coverage = 0;
  return p;
}
}  // namespace

Table pages_table(const Context& ctx, const std::vector<std::string>& globs,
                  const std::function<void(int, int)>& progress) {
  const auto set = load_materials(ctx, globs.empty() ? std::vector<std::string>{"**"} : globs,
                                  every_page(), progress);
  Table t;
  t.name = "pages";
  t.title = "Database pages";
  t.columns = {{"page"}, {"book"},        {"book_name"}, {"section"},
               {"kind"}, {"kind_detail"}, {"class"}};
  add_coverage_columns(t);
  t.columns.insert(t.columns.end(), {{"reference"}, {"status"}});
  std::map<std::string, std::vector<Cell>> rows;  // sorted by page
  const auto& pages = *ctx.settings().paths.pages;
  for (const auto& m : set.materials) {
    auto row = page_row(m.material.source, pages.find(m.material.source));
    row.push_back(std::string(spectral::to_string(m.material.material_class)));
    add_coverage_cells(row, m);
    row.insert(row.end(), {m.material.reference, std::string("ok")});
    rows[m.material.source] = std::move(row);
  }
  for (const auto& s : set.skipped) {
    auto row = page_row(s.spec, pages.find(s.spec));
    row.insert(row.end(), {std::string(), std::nan(""), std::nan(""), std::nan(""), std::string(),
                           std::string(), s.reason});
    rows[s.spec] = std::move(row);
  }
  for (auto& [page, row] : rows) t.rows.push_back(std::move(row));
  t.reading = fmt::format("{} pages: {} read, {} that cannot be read (status says why).",
                          rows.size(), set.materials.size(), set.skipped.size());
  t.notes = {setting_note(ctx),
             "kind: bulk, thin film, nanostructure, model, computed (DFT and other computed "
             "data), variant (away from room temperature or under pressure) or unlisted, from the "
             "catalog's section and page name (docs/consensus.md, \"Page kinds\"); kind_detail: "
             "a film's thickness, a particle's radius, a temperature.",
             "class: metal when the mean k over 400-700 nm exceeds 0.5 (light entering is absorbed "
             "within 0.1 µm), "
             "dielectric otherwise.",
             coverage_note([&] {
               std::vector<const LoadedMaterial*> all;
               for (const auto& m : set.materials) all.push_back(&m);
               return all;
             }())};
  return t;
}

Library build_library(const Context& ctx, const LibraryOptions& options,
                      const std::function<void(int, int)>& load_progress,
                      const std::function<void(int, int)>& fit_progress) {
  LoadPolicy policy;
  policy.min_coverage = options.min_coverage;
  policy.only = options.only;
  policy.strict = options.strict;
  Library lib;
  lib.set = load_materials(ctx, options.globs, policy, load_progress);
  StudyOptions study;
  study.fit_tolerance = kLibraryFitTolerance;
  auto studies = study_materials(ctx, lib.set.materials, study, fit_progress);
  lib.consensus = build_consensus(ctx, page_groups(studies), study);
  std::map<std::string, const MaterialStudy*> by_group;
  for (size_t i = 0; i < lib.consensus.groups.size(); ++i)
    by_group[lib.consensus.groups[i].name] = &lib.consensus.studies[i];
  // Each page's group consensus, if it comes first before the page; then the pages' studies move
  // into the rows, and the consensus's pointers to them follow.
  std::vector<const MaterialStudy*> before(studies.size(), nullptr);
  for (size_t i = 0; i < studies.size(); ++i) {
    if (!find_distance(lib.consensus, studies[i])) continue;
    const auto it = by_group.find(spread_group(studies[i].material->material.source));
    if (it != by_group.end()) before[i] = it->second, by_group.erase(it);
  }
  std::vector<size_t> row_of(studies.size());
  lib.rows.reserve(studies.size() + lib.consensus.studies.size());
  for (size_t i = 0; i < studies.size(); ++i) {
    if (before[i]) lib.rows.push_back(*before[i]);
    row_of[i] = lib.rows.size();
    lib.rows.push_back(std::move(studies[i]));
  }
  for (auto& g : lib.consensus.groups)
    for (auto& p : g.pages)
      p.page = &lib.rows[row_of[static_cast<size_t>(p.page - studies.data())]];
  return lib;
}

namespace {

// Every quality flag of a page: extrapolated, each model's fit flags, the values out of range.
std::string quality_flags(const MaterialStudy& s, const std::string& out_of_range) {
  std::vector<std::string> flags;
  if (s.material->coverage.extrapolated) flags.push_back("extrapolated");
  for (const auto& r : s.models) {
    const std::string f = fit::fit_flags(r.fitted);
    for (const auto flag : spectral::split_fields(f, " "))
      flags.push_back(std::string(fresnel::model_spec(r.model).name) + ":" + std::string(flag));
  }
  for (const auto value : spectral::split_fields(out_of_range, " "))
    flags.push_back("out_of_range:" + std::string(value));
  std::string out;
  for (const auto& f : flags) out += (out.empty() ? "" : " ") + f;
  return out;
}

}  // namespace

namespace {

// The page kind, the distance from the consensus and the outlier flag of a page; the uncertainty
// of a consensus row.
void add_consensus_columns(Table& t, const std::vector<MaterialStudy>& studies,
                           const ConsensusSet& set) {
  t.columns.insert(t.columns.end(), {{"kind"},
                                     {"kind_detail"},
                                     {"consensus_f0_de00", 3},
                                     {"consensus_f82_de00", 3},
                                     {"outlier"},
                                     {"outlier_reason"},
                                     {"spread_f0_de00_median", 3},
                                     {"spread_f0_de00_max", 3},
                                     {"spread_f82_de00_median", 3},
                                     {"spread_f82_de00_max", 3},
                                     {"spread_f0_lo"},
                                     {"spread_f0_hi"},
                                     {"spread_f82_lo"},
                                     {"spread_f82_hi"}});
  const auto rgb = [](const color::Rgb& v) {
    return fmt::format("{:.4f} {:.4f} {:.4f}", v.r, v.g, v.b);
  };
  for (size_t i = 0; i < studies.size(); ++i) {
    const auto& m = studies[i].material->material;
    auto& row = t.rows[i];
    const ConsensusGroup* g = nullptr;
    for (size_t c = 0; c < set.studies.size(); ++c)
      if (set.studies[c].material == studies[i].material) g = &set.groups[c];
    if (g) {
      row.insert(row.end(), {std::string("consensus"), m.section, NAN, NAN, std::string(),
                             std::string(), g->f0_median, g->f0_max, g->f82_median, g->f82_max,
                             rgb(g->f0_lo), rgb(g->f0_hi), rgb(g->f82_lo), rgb(g->f82_hi)});
      continue;
    }
    const auto* d = find_distance(set, studies[i]);
    row.insert(row.end(),
               {m.origin == spectral::Material::Origin::Page
                    ? std::string(spectral::to_string(m.page_class.kind))
                : m.origin == spectral::Material::Origin::Catalog ? std::string("catalog")
                                                                  : std::string("file"),
                m.page_class.detail, d ? d->f0_de00 : NAN, d ? d->f82_de00 : NAN,
                std::string(d ? (d->outlier ? "yes" : "no") : ""), d ? d->reason : std::string(),
                NAN, NAN, NAN, NAN, std::string(), std::string(), std::string(), std::string()});
  }
}

}  // namespace

Table library_table(const Context& ctx, const std::vector<MaterialStudy>& studies,
                    const ConsensusSet* consensus) {
  Table t = presets_table(ctx, studies);
  t.name = "library";
  t.title = fmt::format("Preset library in {}: {} pages", ctx.settings().space, studies.size());
  const int out_of_range = column_index(t, "out_of_range");
  t.columns.insert(t.columns.end(), {{"book"}, {"section"}, {"uncovered"}});
  for (const auto& spec : fresnel::model_specs())
    for (const char* kind : {"derived", "fitted"})
      t.columns.push_back({fmt::format("{}_{}_rms", spec.name, kind), 3});
  t.columns.insert(t.columns.end(), {{"flags"}, {"warnings", 0}});
  int flagged = 0;
  for (size_t i = 0; i < studies.size(); ++i) {
    const auto& s = studies[i];
    const auto& m = s.material->material;
    auto& row = t.rows[i];
    row.reserve(t.columns.size());
    row.insert(
        row.end(),
        {m.origin == spectral::Material::Origin::Page ? spectral::book_of(m.source) : std::string(),
         m.section, s.material->coverage.uncovered});
    for (const auto& r : s.models) row.insert(row.end(), {r.derived_error.rms, r.fitted_error.rms});
    const std::string flags = quality_flags(s, std::get<std::string>(row[out_of_range]));
    flagged += !flags.empty();
    row.insert(row.end(), {flags, static_cast<long long>(s.material->warnings.size())});
  }
  if (consensus) add_consensus_columns(t, studies, *consensus);
  t.reading = fmt::format(
      "{} pages, {} of them flagged. Every value comes with its flags: a page whose data does "
      "not cover the visible range is marked extrapolated and says which wavelengths it holds.",
      studies.size(), flagged);
  t.notes.push_back(
      "flags: extrapolated (see uncovered); MODEL:at_bound:NAME, MODEL:iteration_limit, "
      "MODEL:kept_start "
      "(the fit's flags, models table); out_of_range:NAME (a value outside [0, 1]); warnings: what "
      "the "
      "reader dropped or merged outside 360-830 nm.");
  if (consensus) {
    t.notes.push_back(
        "kind: the page's kind from the database catalog (docs/consensus.md), catalog for a "
        "catalog entry, file for a file; consensus rows (source GROUP/consensus, named by the "
        "element's common name) are the per-wavelength median of the group's bulk pages' "
        "reflectance at "
        "0° and arccos(1/7); consensus_f0_de00, consensus_f82_de00: a page's ΔE2000 from its "
        "group's consensus; spread_*: a consensus row's uncertainty, the median and largest "
        "distance of its bulk pages, and the lowest and highest F0 and F82 of each channel over "
        "them (r g b, working space); kind_detail says how many pages, a single page being no "
        "consensus.");
    t.notes.push_back(fmt::format(
        "outlier: beyond the bulk pages' median distance + {:g} × {:g} × MAD and beyond {:g} "
        "ΔE2000, in F0 or F82.",
        kOutlierMads, kMadToSigma, kOutlierMinDe00));
  }
  return t;
}

std::string reason_class(const std::string& reason) {
  std::string r = reason;
  // "FILE: ..." or "FILE:LINE: ...", where FILE is a .yml path (which may hold spaces).
  if (const auto yml = r.find(".yml:"); yml != std::string::npos) {
    size_t p = yml + 5;
    while (p < r.size() && std::isdigit(static_cast<unsigned char>(r[p]))) ++p;
    if (p < r.size() && r[p] == ':') ++p;
    r = r.substr(p + (p < r.size() && r[p] == ' '));
  }
  r = r.substr(0, r.find(" ("));
  std::string out;
  for (size_t i = 0; i < r.size(); ++i) {
    // A number starts with a digit (or a sign before one) that does not end a word ("n2" stays).
    const bool digit = std::isdigit(static_cast<unsigned char>(r[i])) &&
                       (i == 0 || !std::isalpha(static_cast<unsigned char>(r[i - 1])));
    const bool sign = (r[i] == '-' || r[i] == '+') && i + 1 < r.size() &&
                      std::isdigit(static_cast<unsigned char>(r[i + 1])) &&
                      (i == 0 || !std::isalnum(static_cast<unsigned char>(r[i - 1])));
    if (!digit && !sign) {
      out += r[i];
      continue;
    }
    while (i + 1 < r.size() &&
           (std::isalnum(static_cast<unsigned char>(r[i + 1])) || r[i + 1] == '.' ||
            ((r[i + 1] == '-' || r[i + 1] == '+') && (r[i] == 'e' || r[i] == 'E'))))
      ++i;
    out += 'N';
  }
  return out;
}

Table skipped_table(const std::vector<SkippedMaterial>& skipped) {
  Table t;
  t.name = "skipped";
  t.title = fmt::format("Pages left out of the library: {}", skipped.size());
  t.columns = {{"page"}, {"reason_class"}, {"reason"}};
  for (const auto& s : skipped) t.rows.push_back({s.spec, reason_class(s.reason), s.reason});
  return t;
}

Table skip_reasons_table(const std::vector<SkippedMaterial>& skipped) {
  std::map<std::string, std::pair<long long, std::string>>
      by_reason;  // class → (count, first page)
  for (const auto& s : skipped) {
    auto& e = by_reason[reason_class(s.reason)];
    if (e.first++ == 0) e.second = s.spec;
  }
  std::vector<std::pair<std::string, std::pair<long long, std::string>>> sorted(by_reason.begin(),
                                                                                by_reason.end());
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const auto& a, const auto& b) { return a.second.first > b.second.first; });
  Table t;
  t.name = "skip_reasons";
  t.title = "Pages left out, by reason";
  t.columns = {{"reason"}, {"pages", 0}, {"example"}};
  for (const auto& [reason, e] : sorted) t.rows.push_back({reason, e.first, e.second});
  return t;
}

}  // namespace fl::analysis
