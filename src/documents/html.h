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

#include "analysis/tables/table.h"
#include "io/image.h"

namespace fl::report {

// Text for HTML element content and attribute values (& < > " ' escaped).
std::string html_escape(const std::string& text);

// One table as an HTML fragment: its title (heading level `heading_level`), reading, a filter box,
// the <table> with every column (numbers printed as in Markdown, with their full value in data-v
// for sorting; non-finite numbers shown as n/a and sorted last) and the notes. `id` names it.
std::string table_html(const analysis::Table& t, const std::string& id, int heading_level = 2);

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
  std::vector<Rgb8> strip;  // ground truth display colours at equally spaced angles 0°…90°
  Rgb8 f0, f82;             // display colours of F0 and F82
  std::vector<std::string> flags;
  std::vector<std::pair<std::string, std::string>> facts;    // (label, value) lines, e.g. errors
  std::vector<std::pair<std::string, std::string>> figures;  // (caption, image path)
  Flip flip;                                                 // none when flip.image is empty
};

// The gallery: a search box (matching name, class, source, flags and facts) and one card per entry.
std::string gallery_html(const std::vector<GalleryEntry>& entries);

struct HtmlReport {
  std::string title;
  std::vector<std::string> intro;  // paragraphs
  std::vector<GalleryEntry> gallery;
  std::span<const analysis::Table> tables;                 // the caller's, shown in order
  std::vector<std::pair<std::string, std::string>> links;  // (text, href): the other formats
  // (caption, image path): figures shown full width before the tables, each opening full size.
  std::vector<std::pair<std::string, std::string>> figures;
  // Findings shown first, one Markdown line each (inline code, links and **bold**).
  std::vector<std::string> summary;
  // (caption, image path): look-dev contact sheets shown after the figures, each opening full size.
  std::vector<std::pair<std::string, std::string>> lookdev;
  std::string lookdev_reading;  // Markdown paragraph above the sheets (may be empty)
};

// The whole page. The same report gives the same bytes.
std::string html_report(const HtmlReport& report);

}  // namespace fl::report
