#include "jobs/library_files.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <span>

#include "analysis/consensus/spread.h"
#include "analysis/render/figure_data.h"
#include "analysis/study/table_notes.h"
#include "analysis/tables/tables.h"
#include "documents/grouped_gallery.h"
#include "documents/html.h"
#include "documents/preset_formats.h"
#include "documents/table_formats.h"
#include "draw/png.h"
#include "jobs/pictures.h"
#include "spectral/pages.h"
#include "spectral/text_file.h"
#include "util/errors.h"
#include "util/parallel.h"
#include "util/suggest.h"

namespace fl::jobs {
namespace {

// The library's preset documents, one line each (documents/preset_formats.h); the tables hold one
// row per page (presets, every model's RMS ΔE2000, flags).
std::string preset_files_markdown() {
  std::string md =
      "- The presets of every page in every preset format (the tables: one row per page with its "
      "presets, every model's RMS ΔE2000 and flags):\n";
  for (const auto& f : documents::preset_file_names("library"))
    md += fmt::format("  - [{0}]({0}): {1}\n", f.path, f.summary);
  return md;
}

// The cards index.html sets in the page (whole groups, at least this many: a first screen at
// 1280 px, 4 columns of 2 rows, and the next); the other groups load as they near the screen.
constexpr size_t kFirstScreenCards = 12;

// The ground truth's colour from 0° to 90° (3 samples per degree), 24 pixels tall.
constexpr int kStripSamples = 270, kStripHeight = 24;

std::string strip_png(const analysis::Context& ctx, const analysis::MaterialStudy& s) {
  analysis::FigureRequest in;
  in.material = s.material->material.name;
  in.parameter_kind = "derived";
  in.ior = &s.material->ior;
  const auto d = analysis::strip_data(ctx, in, {{0.0, 90.0, kStripSamples}});
  io::Image8 img(kStripSamples, kStripHeight);
  for (int x = 0; x < kStripSamples; ++x)
    for (int y = 0; y < kStripHeight; ++y) {
      const auto* p = &d.rows.front().srgb[3 * static_cast<size_t>(x)];
      img.set(x, y, {p[0], p[1], p[2]});
    }
  return draw::encode_png(img);
}

// The models table (every page × model × parameter set: the library's largest, 20 rows and 17 cells
// per page) made and written kModelsPart pages at a time, so only one part's cells are held beside
// the CSV text; a part of 64 pages (about 1,300 rows) costs nothing measurable against the whole.
constexpr size_t kModelsPart = 64;
std::string models_csv(const analysis::Context& ctx,
                       const std::vector<analysis::MaterialStudy>& rows) {
  const std::span<const analysis::MaterialStudy> all(rows);
  std::string out;
  for (size_t start = 0; start < all.size() || start == 0; start += kModelsPart) {
    const auto t =
        analysis::models_table(ctx, all.subspan(start, std::min(kModelsPart, all.size() - start)));
    out += start == 0 ? documents::to_csv(t) : documents::to_csv_rows(t);
  }
  return out;
}

std::string file_safe(std::string s) {
  for (auto& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
  return s;
}

// The flags of one library row, space-separated in its flags column.
std::vector<std::string> row_flags(const Table& t, size_t row) {
  std::vector<std::string> out;
  for (const auto f :
       spectral::split_fields(std::get<std::string>(t.rows[row][column_index(t, "flags")]), " "))
    out.emplace_back(f);
  return out;
}

std::string rgb_text(const color::Rgb& v) {
  return fmt::format("({:.3f}, {:.3f}, {:.3f})", v.r, v.g, v.b);
}

// One gallery entry: the strip, F0 and F82, class and coverage, and the flags, with the reason a
// colour may not be measured.
std::string gallery_entry(const analysis::MaterialStudy& s, const std::string& strip,
                          const std::string& flags) {
  const auto& m = *s.material;
  std::string out =
      fmt::format("### {}\n\n![{}]({})\n\n{} · F0 {} · F82 {} · coverage {:.4f}", m.material.source,
                  m.material.source, strip, spectral::to_string(m.material.material_class),
                  rgb_text(s.derived.f0), rgb_text(s.derived.f82), m.coverage.both);
  if (!m.material.section.empty()) out += " · " + m.material.section;
  out += "\n\n";
  if (m.coverage.extrapolated)
    out += fmt::format(
        "**Extrapolated**: {}; the colours there are the nearest measured value held, not a "
        "measurement.\n\n",
        m.coverage.uncovered);
  if (!flags.empty()) out += "Flags: `" + flags + "`\n\n";
  return out;
}

std::string gallery(const analysis::Context& ctx, const analysis::Library& lib, const Table& t,
                    io::Files& files) {
  const size_t n = lib.rows.size();
  std::vector<std::string> pngs(n);
  parallel_for(n, [&](size_t i) { pngs[i] = strip_png(ctx, lib.rows[i]); });
  std::string md =
      "# Preset library gallery\n\nPer page: the spectral ground truth's colour from 0° (left) to "
      "90° "
      "(right), F0 and F82 in the working space, and the page's flags.\n\n" +
      analysis::setting_note(ctx) + "\n\n";
  std::string book;
  for (size_t i = 0; i < n; ++i) {
    const auto& mat = lib.rows[i].material->material;
    const std::string b = mat.book_name.empty() ? spectral::book_of(mat.source) : mat.book_name;
    if (b != book) md += "## " + b + "\n\n", book = b;
    const std::string path = "strips/" + file_safe(mat.source) + ".png";
    files.emplace_back(path, std::move(pngs[i]));
    md += gallery_entry(lib.rows[i], path,
                        std::get<std::string>(t.rows[i][column_index(t, "flags")]));
  }
  return md;
}

// Pages carrying each kind of flag, from the library table's flags column.
std::map<std::string, int> flag_counts(const Table& t) {
  std::map<std::string, int> counts;
  for (size_t row = 0; row < t.rows.size(); ++row) {
    std::map<std::string, bool> kinds;
    for (const auto& token : row_flags(t, row)) {
      const bool range = token.rfind("out_of_range:", 0) == 0;
      std::string kind = range ? "out_of_range" : token == "extrapolated" ? token : "";
      for (const char* fit : {"at_bound", "iteration_limit", "kept_start", "no_usable_solution"})
        if (!range && token.find(std::string(":") + fit) != std::string::npos)
          kind = std::string("fit ") + fit;
      kinds[kind.empty() ? token : kind] = true;
    }
    for (const auto& [k, v] : kinds) ++counts[k];
  }
  return counts;
}

std::string readme(const analysis::Context& ctx, const analysis::Library& lib, const Table& t,
                   const std::string& command, bool gallery) {
  int metals = 0;
  for (const auto& m : lib.set.materials)
    metals += m.material.material_class == spectral::MaterialClass::Metal;
  std::string md = fmt::format("# Fresnel Lab preset library\n\nGenerated by `{}`. {}\n\n", command,
                               analysis::setting_note(ctx));
  md += fmt::format(
      "- Pages matched: {}\n- In the library: {} ({} metals, {} dielectrics)\n- Skipped: {}\n\n",
      lib.set.requested, lib.set.materials.size(), metals, lib.set.materials.size() - metals,
      lib.set.skipped.size());
  md += "## Flags (pages carrying each)\n\n| flag | pages |\n|---|---|\n";
  for (const auto& [flag, n] : flag_counts(t)) md += fmt::format("| {} | {} |\n", flag, n);
  md += "\n" + documents::to_markdown(analysis::skip_reasons_table(lib.set.skipped), 2);
  md += "\n## Files\n\n" + preset_files_markdown() +
        "- [models.csv](models.csv): every model's derived and fitted parameters and errors per "
        "page\n"
        "- [skipped.csv](skipped.csv): every page left out, with its reason\n- "
        "[spread.md](spread.md), "
        "[spread.csv](spread.csv): the spread between pages of the same metal\n"
        "- [consensus.md](consensus.md), [consensus_pages.md](consensus_pages.md), "
        "[outlier_kinds.md](outlier_kinds.md) (and .csv): each metal's consensus of its bulk "
        "pages with its uncertainty, every page's kind and distance from it, outliers per page "
        "kind (docs/consensus.md)\n";
  if (gallery) md += "- [gallery.md](gallery.md): a colour strip per page\n";
  md +=
      "- [index.html](index.html): the library as a searchable gallery (colour strip, F0 and F82 "
      "swatches, kind, flags) grouped by element, and every table above, sortable and filterable; "
      "`cards/` holds the groups' cards the page loads as they near the screen, `tables/` the "
      "large tables it loads when they are opened\n";
  return md;
}

// A card's kind and its place against the consensus: a page's kind and distance (with the outlier
// reason), a consensus's spread (its bulk pages' median and largest ΔE2000).
std::pair<std::string, std::string> consensus_fact(const Table& t, size_t row) {
  const auto text = [&](const char* col) {
    return std::get<std::string>(t.rows[row][column_index(t, col)]);
  };
  const auto number = [&](const char* col) {
    return std::get<double>(t.rows[row][column_index(t, col)]);
  };
  const std::string kind = text("kind"), detail = text("kind_detail");
  if (kind == "consensus")
    return {"consensus",
            fmt::format("{}; spread F0 {:.2f} / {:.2f}, F82 {:.2f} / {:.2f} ΔE2000 (median / "
                        "max); the pages' F0 from ({}) to ({}), F82 from ({}) to ({})",
                        detail, number("spread_f0_de00_median"), number("spread_f0_de00_max"),
                        number("spread_f82_de00_median"), number("spread_f82_de00_max"),
                        text("spread_f0_lo"), text("spread_f0_hi"), text("spread_f82_lo"),
                        text("spread_f82_hi"))};
  std::string value = kind + (detail.empty() ? "" : " " + detail);
  if (!std::isnan(number("consensus_f0_de00")))
    value += fmt::format("; from the consensus F0 {:.2f}, F82 {:.2f} ΔE2000",
                         number("consensus_f0_de00"), number("consensus_f82_de00"));
  if (text("outlier") == "yes") value += "; outlier";
  return {"kind", value};
}

// A main-shelf page's book ("Au" of main/Au/nk/Johnson, and of the consensus main/Au/consensus);
// empty for other shelves, catalog entries and files.
std::string main_book(const spectral::Material& m) {
  if (m.origin != spectral::Material::Origin::Page &&
      m.origin != spectral::Material::Origin::Consensus)
    return {};
  if (m.source.rfind("main/", 0) != 0) return {};
  return m.source.substr(5, m.source.find('/', 5) - 5);
}

// A book's name as the catalog gives it, its markup removed ("Al<sub>2</sub>O<sub>3</sub> (...)"
// → "Al2O3 (...)").
std::string plain(const std::string& book_name) {
  std::string out;
  bool tag = false;
  for (const char c : book_name) {
    if (c == '<' || c == '>')
      tag = c == '<';
    else if (!tag)
      out += c;
  }
  return out;
}

// "Au (Gold)" → "gold".
std::string common_name(const std::string& book_name) {
  const auto open = book_name.find('('), close = book_name.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close < open) return {};
  return ascii_lower(book_name.substr(open + 1, close - open - 1));
}

// Per book of the main shelf, the names and aliases of the catalog entries measured on it
// ("Al": Aluminum, aluminium, Al).
std::map<std::string, std::vector<std::string>> catalog_names_by_book(
    const analysis::Context& ctx) {
  std::map<std::string, std::vector<std::string>> out;
  std::vector<spectral::Material> catalog;
  try {
    catalog = spectral::read_catalog(ctx.settings().paths);
  } catch (const InputError&) {
    return out;  // no catalog: the search keeps the database's names
  }
  for (const auto& m : catalog) {
    if (m.source.rfind("main/", 0) != 0) continue;
    const std::string book = m.source.substr(5, m.source.find('/', 5) - 5);
    auto& names = out[book];
    names.push_back(m.name);
    names.insert(names.end(), m.aliases.begin(), m.aliases.end());
  }
  return out;
}

// The cards' groups (their book, the element for the main shelf: "Au (Gold)"), kinds and search
// keywords (the element's symbol, common name and catalog names and aliases), the cards ordered by
// group: the main shelf's books first, alphabetically, then the other books, then catalog
// entries and files.
void group_cards(const analysis::Context& ctx, const analysis::Library& lib, const Table& t,
                 std::vector<documents::GalleryEntry>& cards) {
  std::map<std::string, std::string> main_names;  // consensus rows take their book's name
  for (const auto& st : lib.rows)
    if (const auto& m = st.material->material; !m.book_name.empty() && !main_book(m).empty())
      main_names.emplace(main_book(m), plain(m.book_name));
  const auto catalog = catalog_names_by_book(ctx);
  const int kind = column_index(t, "kind");
  std::vector<std::pair<std::string, size_t>> order;  // (sort key, card)
  for (size_t i = 0; i < cards.size(); ++i) {
    const auto& m = lib.rows[i].material->material;
    const std::string book = main_book(m);
    auto& c = cards[i];
    c.kind = std::get<std::string>(t.rows[i][kind]);
    c.group = !book.empty() && main_names.count(book) ? main_names[book]
              : !m.book_name.empty()                  ? plain(m.book_name)
              : !book.empty()                         ? book
                                                      : "catalog entries and files";
    const bool page = m.origin == spectral::Material::Origin::Page ||
                      m.origin == spectral::Material::Origin::Consensus;
    order.emplace_back((!page ? "2" : book.empty() ? "1" : "0") + ascii_lower(c.group), i);
    if (!page) continue;
    const auto symbol = c.group.substr(0, c.group.find(" ("));
    c.keywords = {symbol, common_name(c.group)};
    if (const auto it = catalog.find(book); it != catalog.end())
      c.keywords.insert(c.keywords.end(), it->second.begin(), it->second.end());
  }
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<documents::GalleryEntry> sorted;
  for (const auto& [key, i] : order) sorted.push_back(std::move(cards[i]));
  cards = std::move(sorted);
}

// index.html, its card scripts and its large tables' scripts: a gallery card per page (strip,
// F0/F82 swatches, flags, coverage, errors) grouped by element, searchable, then `tables` (the
// library table first: the cards read it), sortable and filterable.
io::Files library_page(const analysis::Context& ctx, const analysis::Library& lib,
                       std::vector<Table> tables, const std::string& command) {
  const Table& t = tables.front();
  documents::HtmlReport page;
  page.title = "Fresnel Lab preset library";
  page.intro = {"Generated by `" + command +
                    "`: presets of database pages, every model's error against spectral "
                    "ground truth (ΔE2000) and each page's flags. The same tables are in CSV, "
                    "Markdown and JSON beside this page.",
                analysis::setting_note(ctx)};
  std::vector<documents::GalleryEntry> cards;
  for (size_t i = 0; i < lib.rows.size(); ++i) {
    const auto& st = lib.rows[i];
    auto card = study_card(ctx, st, row_flags(t, i));
    card.key = file_safe(st.material->material.source);
    const auto& c = st.material->coverage;
    card.facts.insert(
        card.facts.begin(),
        {"coverage",
         fmt::format("{:.4f}{}", c.both, c.uncovered.empty() ? "" : " (" + c.uncovered + ")")});
    card.facts.insert(card.facts.begin(), consensus_fact(t, i));
    cards.push_back(std::move(card));
  }
  group_cards(ctx, lib, t, cards);
  auto gallery = documents::grouped_gallery(cards, kFirstScreenCards, "cards");
  page.gallery_fragment = std::move(gallery.html);
  page.gallery_script = std::move(gallery.script);
  page.tables = std::move(tables);
  page.links = {{"README.md", "README.md"}};
  for (const auto& f : documents::preset_file_names("library"))
    page.links.emplace_back(f.path, f.path);
  io::Files files = documents::html_report_files(page, "tables");
  for (auto& f : gallery.files) files.push_back(std::move(f));
  return files;
}

}  // namespace

io::Files library_files(const analysis::Context& ctx, const analysis::Library& lib,
                        bool with_gallery, const std::string& command) {
  auto t = analysis::library_table(ctx, lib.rows, &lib.consensus);
  auto spread = analysis::spread_table(ctx, lib.rows);  // the consensus rows are in no group
  auto consensus = analysis::consensus_table(ctx, lib.consensus);
  auto consensus_pages = analysis::consensus_pages_table(lib.consensus);
  auto kinds = analysis::outlier_kinds_table(lib.consensus);
  auto skipped = analysis::skipped_table(lib.set.skipped);
  // The documents made side by side, each part's files in a fixed order.
  std::array<io::Files, 4> parts;
  parallel_for_all(parts.size(), [&](size_t i) {
    auto& files = parts[i];
    if (i == 0) files = documents::preset_files("library", {ctx, lib.rows, t});
    if (i == 1) files.emplace_back("models.csv", models_csv(ctx, lib.rows));
    if (i == 2) {
      files.emplace_back("skipped.csv", documents::to_csv(skipped));
      files.emplace_back("spread.csv", documents::to_csv(spread));
      files.emplace_back("spread.md", documents::to_markdown(spread));
      for (const auto* c : {&consensus, &consensus_pages, &kinds}) {
        files.emplace_back(c->name + ".csv", documents::to_csv(*c));
        files.emplace_back(c->name + ".md", documents::to_markdown(*c));
      }
    }
    if (i == 3 && with_gallery) files.emplace_back("gallery.md", gallery(ctx, lib, t, files));
  });
  io::Files files;
  for (auto& part : parts)
    for (auto& f : part) files.push_back(std::move(f));
  std::string about = readme(ctx, lib, t, command, with_gallery);
  // The page last: it takes the tables (the library table the largest) rather than copies.
  std::vector<Table> tables;
  for (auto* table : {&t, &consensus, &kinds, &spread}) tables.push_back(std::move(*table));
  tables.push_back(analysis::skip_reasons_table(lib.set.skipped));
  tables.push_back(std::move(skipped));
  for (auto& f : library_page(ctx, lib, std::move(tables), command)) files.push_back(std::move(f));
  files.emplace_back("README.md", std::move(about));
  return files;
}

}  // namespace fl::jobs
