#pragma once
// The static HTML report: one self-contained index.html (every style and script inline, images
// referenced beside it, nothing fetched from a network) built from the same tables as the CSV and
// Markdown files. Tables sort when a header is clicked and narrow to the rows matching a filter;
// the gallery narrows to the materials matching its search; a flip toggles a sphere between the
// ground truth and a model on click, previewing each model on hover.
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "io/image.h"
#include "util/table.h"

namespace fl::documents {

// Text for HTML element content and attribute values (& < > " ' escaped).
std::string html_escape(const std::string& text);

// One table as an HTML fragment: its title (heading level `heading_level`), reading, a filter box,
// the <table> with every column (numbers printed as in Markdown, with their full value in data-v
// for sorting; non-finite numbers shown as n/a and sorted last) and the notes. `id` names it.
std::string table_html(const Table& t, const std::string& id, int heading_level = 2);

// A sphere flip: frames side by side in one image (each frame_px square), frame 0 the truth.
struct Flip {
  std::string image;  // path relative to the page
  int frame_px = 0;
  std::vector<std::string> labels;  // one per frame
};

// One material of the gallery.
struct GalleryEntry {
  std::string key;  // unique; the card's anchor
  std::string name, material_class, source;
  std::string kind;  // what the entry is ("bulk", "thin film", "consensus", "catalog", "file")
  // Other names the search finds it by: its element's symbol and common name, catalog aliases.
  std::vector<std::string> keywords;
  std::string group;  // the element it is grouped under (grouped_gallery), e.g. "Au (Gold)"
  std::vector<io::Rgb8> strip;  // ground truth display colours at equally spaced angles 0°…90°
  io::Rgb8 f0, f82;             // display colours of F0 and F82
  std::vector<std::string> flags;
  std::vector<std::pair<std::string, std::string>> facts;    // (label, value) lines, e.g. errors
  std::vector<std::pair<std::string, std::string>> figures;  // (caption, image path)
  Flip flip;                                                 // none when flip.image is empty
};

// The gallery: a search box (gallery_search_text) and one card per entry.
std::string gallery_html(const std::vector<GalleryEntry>& entries);
// What the search matches a card by: name, class, kind, source, keywords and flags (not the
// facts, whose wording every card shares).
std::string gallery_search_text(const GalleryEntry& e);
// One card (an <article>).
std::string gallery_card_html(const GalleryEntry& e);

struct HtmlReport {
  std::string title;
  std::vector<std::string> intro;  // paragraphs
  std::vector<GalleryEntry> gallery;
  std::span<const Table> tables;                           // the caller's, shown in order
  std::vector<std::pair<std::string, std::string>> links;  // (text, href): the other formats
  // (caption, image path): figures shown full width before the tables, each opening full size.
  std::vector<std::pair<std::string, std::string>> figures;
  // Findings shown first, one Markdown line each (inline code, links and **bold**).
  std::vector<std::string> summary;
  // (caption, image path): look-dev contact sheets shown after the figures, each opening full size.
  std::vector<std::pair<std::string, std::string>> lookdev;
  std::string lookdev_reading;  // Markdown paragraph above the sheets (may be empty)
  // A prepared gallery section (grouped_gallery's html) shown instead of `gallery`, and the script
  // that runs it, when not empty.
  std::string gallery_fragment, gallery_script;
};

// The whole page, every table in it. The same report gives the same bytes.
std::string html_report(const HtmlReport& report);

// Tables larger than this are left out of a page written with html_report_files.
inline constexpr size_t kInlineTableBytes = 256 * 1024;

// The page as ("index.html", bytes) followed by the scripts beside it: each table larger than
// kInlineTableBytes in FOLDER/NAME.js, which the page loads when the table's section is first
// opened (so a library of thousands of rows opens as fast as a small one). Paths relative to the
// page.
std::vector<std::pair<std::string, std::string>> html_report_files(const HtmlReport& report,
                                                                   const std::string& folder);

// `text` as a JavaScript string literal, safe inside a <script> element and in a .js file.
std::string js_string(const std::string& text);

}  // namespace fl::documents
