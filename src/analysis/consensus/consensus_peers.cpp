// Published presets (physicallybased.info, the OpenPBR examples) against the consensus.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "analysis/consensus/consensus.h"
#include "analysis/consensus/spread.h"
#include "analysis/study/table_notes.h"
#include "color/lab.h"
#include "spectral/text_file.h"
#include "util/errors.h"

namespace fl::analysis {

namespace {

// The rows of a small CSV file with a header, each checked for `fields` comma-separated fields.
std::vector<std::vector<std::string>> read_csv_rows(const std::string& path, size_t fields) {
  const std::string text = spectral::read_text_file(path);
  std::vector<std::vector<std::string>> rows;
  const auto lines = spectral::split_lines(text);
  for (size_t i = 1; i < lines.size(); ++i) {
    if (spectral::trim(lines[i]).empty()) continue;
    std::vector<std::string> row;
    for (const auto f : spectral::split_fields(lines[i], ",")) row.emplace_back(spectral::trim(f));
    if (row.size() != fields)
      throw InputError(fmt::format("{}:{}: expected {} comma-separated fields, found {}", path,
                                   i + 1, fields, row.size()));
    rows.push_back(std::move(row));
  }
  return rows;
}

double number(const std::string& path, const std::string& field) {
  double v = 0;
  if (!spectral::parse_finite(field, v))
    throw InputError(fmt::format("{}: '{}' is not a number", path, field));
  return v;
}

struct Published {
  std::string page;
  color::Rgb f0{NAN, NAN, NAN}, f82_tint{NAN, NAN, NAN};
  std::string openpbr_file;
};

std::map<std::string, Published> read_peers(const std::string& dir) {
  std::map<std::string, Published> out;
  for (const auto& r : read_csv_rows(dir + "/physicallybased_pages.csv", 2)) out[r[0]].page = r[1];
  const std::string values = dir + "/physicallybased.csv";
  for (const auto& r : read_csv_rows(values, 7)) {
    if (r[2] != "acescg" || (r[3] != "f0" && r[3] != "f82tint") || !out.count(r[0])) continue;
    auto& v = r[3] == "f0" ? out[r[0]].f0 : out[r[0]].f82_tint;
    for (int c = 0; c < 3; ++c) v[c] = number(values, r[4 + c]);
  }
  for (const auto& r : read_csv_rows(dir + "/openpbr_examples.csv", 10))
    for (auto& [metal, p] : out) {
      std::string key = metal;
      std::replace(key.begin(), key.end(), ' ', '_');
      if (r[1].rfind(key, 0) == 0 && p.openpbr_file.empty()) p.openpbr_file = r[0];
    }
  return out;
}

// The glob of a page's group (spread_group): its book, or on the alloys shelf its composition.
std::string group_glob(const std::string& page) {
  const std::filesystem::path p(page);
  const std::string book = p.parent_path().parent_path().generic_string();
  const std::string name = p.filename().string();
  const auto dash = name.find('-');
  if (book.rfind("other/alloys/", 0) != 0 || dash == std::string::npos) return book + "/**";
  return book + "/**-" + name.substr(dash + 1);
}

// The published values have three decimals: rounding one channel of a bright metal's F0 by 0.0005
// moves it by up to about 0.05 ΔE2000, and the published F0 of a page differs from ours of the same
// page by up to 0.15 (published_vs_page_f0_de00, W/Werner-DFT). A preset counts as outside the
// spread only beyond this.
constexpr double kPublishedRoundingDe00 = 0.1;

// OpenPBR's F82 from F0 and specular_color: the tint times Schlick's F(1/7).
color::Rgb f82_from_tint(const color::Rgb& f0, const color::Rgb& tint) {
  const double w = std::pow(1.0 - kConsensusCosGrazing, 5.0);
  color::Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = tint[c] * (f0[c] + (1.0 - f0[c]) * w);
  return out;
}

void add_peer_row(Table& t, const Context& ctx, const std::string& metal, const Published& p,
                  const ConsensusSet& set, std::vector<std::string>& outside) {
  const std::string group = spread_group(p.page);
  const ConsensusGroup* g = nullptr;
  const MaterialStudy* consensus = nullptr;
  for (size_t i = 0; i < set.groups.size(); ++i)
    if (set.groups[i].name == group) g = &set.groups[i], consensus = &set.studies[i];
  const PageDistance* page = nullptr;
  if (g)
    for (const auto& d : g->pages)
      if (d.page->material->material.source == p.page) page = &d;
  std::vector<Cell> row{metal, p.page, p.openpbr_file};
  if (!g) {
    row.insert(row.end(), {std::string(), 0LL, NAN, NAN, NAN, NAN, NAN, NAN, std::string(), NAN,
                           std::string("no consensus: no bulk metal page covers the visible")});
    t.rows.push_back(std::move(row));
    return;
  }
  const auto c0 = ctx.rgb_to_lab(consensus->derived.f0);
  const auto c82 = ctx.rgb_to_lab(consensus->derived.f82);
  const double pub_f0 = color::ciede2000<double>(ctx.rgb_to_lab(p.f0), c0);
  const double pub_f82 =
      color::ciede2000<double>(ctx.rgb_to_lab(f82_from_tint(p.f0, p.f82_tint)), c82);
  // With one bulk page there is no spread: beyond the outlier floor counts as outside.
  const double f0_limit = g->used < 2 ? kOutlierMinDe00 : g->f0_max + kPublishedRoundingDe00;
  const double f82_limit = g->used < 2 ? kOutlierMinDe00 : g->f82_max + kPublishedRoundingDe00;
  const bool out = pub_f0 > f0_limit || pub_f82 > f82_limit;
  const std::string verdict = !out          ? "within"
                              : g->used < 2 ? "outside (one bulk page: beyond 2 ΔE2000 of it)"
                                            : "outside";
  if (out) outside.push_back(metal);
  const double reproduced =
      page ? color::ciede2000<double>(ctx.rgb_to_lab(p.f0), ctx.rgb_to_lab(page->page->derived.f0))
           : NAN;
  row.insert(
      row.end(),
      {page ? std::string(spectral::to_string(page->page->material->material.page_class.kind))
            : std::string("not in the group (class or coverage)"),
       static_cast<long long>(g->used), page ? page->f0_de00 : NAN, page ? page->f82_de00 : NAN,
       pub_f0, pub_f82, g->f0_max, g->f82_max, std::string(page && page->outlier ? "yes" : "no"),
       reproduced, verdict});
  t.rows.push_back(std::move(row));
}

}  // namespace

Table peer_table(const Context& ctx_in, const std::string& peer_dir,
                 const std::function<void(int, int)>& progress) {
  // The published values are ACEScg (D60 white): the comparison is made there.
  Settings s = ctx_in.settings();
  s.space = "acescg";
  s.illuminant.clear();
  const Context ctx(s);
  const auto peers = read_peers(peer_dir);
  std::vector<std::string> globs;
  for (const auto& [metal, p] : peers)
    if (std::find(globs.begin(), globs.end(), group_glob(p.page)) == globs.end())
      globs.push_back(group_glob(p.page));
  const auto pages = study_pages(ctx, globs, progress);
  StudyOptions derived_only;
  derived_only.fit = false;
  derived_only.method_errors = false;
  const auto set = build_consensus(ctx, page_groups(pages.studies), derived_only);
  Table t;
  t.name = "peers";
  t.title = "Published metal presets against the consensus of the measurements (ACEScg, ΔE2000)";
  t.columns = {{"metal"},
               {"page"},
               {"openpbr_example"},
               {"page_kind"},
               {"pages_used", 0},
               {"page_f0_de00", 2},
               {"page_f82_de00", 2},
               {"published_f0_de00", 2},
               {"published_f82_de00", 2},
               {"spread_f0_max", 2},
               {"spread_f82_max", 2},
               {"page_outlier"},
               {"published_vs_page_f0_de00", 2},
               {"published"}};
  std::vector<std::string> outside;
  for (const auto& [metal, p] : peers) add_peer_row(t, ctx, metal, p, set, outside);
  std::string names;
  for (const auto& m : outside) names += (names.empty() ? "" : ", ") + m;
  t.reading = fmt::format(
      "{} of {} published presets lie outside the spread of the bulk measurements (farther from "
      "the consensus than the farthest bulk page, in F0 or F82): {}.",
      outside.size(), peers.size(), names.empty() ? "none" : names);
  t.notes = {
      setting_note(ctx),
      "page: the database page physicallybased.info computed the metal from; page_f0_de00, "
      "page_f82_de00: that page's F0 (F82), from our spectral procedure, against the consensus of "
      "its group's bulk pages; published_*: the published ACEScg f0 and F82 (f82tint × Schlick's "
      "F(1/7)) against the consensus; spread_*_max: the farthest bulk page's distance (0 with one "
      "bulk page: a single measurement has no spread).",
      fmt::format(
          "published: outside when the published F0 or F82 is farther from the consensus than "
          "every bulk measurement by more than {:g} ΔE2000 (the publication's rounding; with one "
          "bulk page, farther than {:g} ΔE2000 from it). page_outlier: yes when the page is an "
          "outlier (consensus "
          "table's rule). published_vs_page_f0_de00: the published F0 against ours from the same "
          "page (how closely the publication is reproduced).",
          kPublishedRoundingDe00, kOutlierMinDe00)};
  return t;
}

}  // namespace fl::analysis
