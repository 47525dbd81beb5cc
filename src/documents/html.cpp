#include "documents/html.h"

#include <fmt/format.h>

#include <cmath>
#include <regex>
#include <vector>

#include "documents/html_assets.h"
#include "documents/table_formats.h"
#include "io/writer.h"

namespace fl::documents {
namespace {

// The page's style: a light, dense layout; tables scroll inside their box with sticky headers.
std::string hex(io::Rgb8 c) {
  return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b);
}

// Markdown's inline code and links in a table's reading and notes, the rest escaped.
std::string inline_markdown(const std::string& text) {
  static const std::regex kCode("`([^`]*)`"), kLink(R"(\[([^\]]*)\]\(([^)\s]*)\))");
  static const std::regex kBold(R"(\*\*([^*]+)\*\*)");
  std::string s = html_escape(text);
  s = std::regex_replace(s, kCode, "<code>$1</code>");
  s = std::regex_replace(s, kBold, "<strong>$1</strong>");
  return std::regex_replace(s, kLink, "<a href=\"$2\">$1</a>");
}

std::string cell_html(const Cell& cell, int precision) {
  if (const auto* text = std::get_if<std::string>(&cell))
    return "<td class=\"t\">" + html_escape(*text) + "</td>";
  if (const auto* n = std::get_if<long long>(&cell))
    return fmt::format("<td data-v=\"{}\">{}</td>", *n, *n);
  const double v = std::get<double>(cell);
  if (!std::isfinite(v)) return "<td data-v=\"\">n/a</td>";
  return fmt::format("<td data-v=\"{}\">{}</td>", format_number(v, 12),
                     format_number(v, precision));
}

std::string strip_gradient(const std::vector<io::Rgb8>& strip) {
  std::string s = "linear-gradient(90deg";
  for (size_t i = 0; i < strip.size(); ++i)
    s += fmt::format(",{} {:.1f}%", hex(strip[i]),
                     strip.size() > 1 ? 100.0 * i / (strip.size() - 1) : 0.0);
  s += ")";
  return s;
}

std::string flip_html(const Flip& f) {
  std::string labels = "[";
  for (size_t i = 0; i < f.labels.size(); ++i)
    labels += (i ? "," : "") + fmt::format("\"{}\"", f.labels[i]);
  labels += "]";
  std::string s = fmt::format(
      "<div class=\"flip\" data-frame=\"0\" data-model=\"1\" data-size=\"{}\" data-labels=\"{}\">"
      "<div class=\"flip-img\" role=\"img\" aria-label=\"sphere render\" title=\"click: truth / "
      "model\" "
      "style=\"width:{}px;height:{}px;background-image:url('{}');background-position:0 0\"></div>"
      "<div class=\"flip-label\">{}</div><div class=\"flip-models\">",
      f.frame_px, html_escape(labels), f.frame_px, f.frame_px, html_escape(f.image),
      html_escape(f.labels.at(0)));
  for (size_t i = 1; i < f.labels.size(); ++i)
    s += fmt::format("<button type=\"button\" data-frame=\"{}\" aria-pressed=\"false\">{}</button>",
                     i, html_escape(f.labels[i]));
  s += "</div></div>";
  return s;
}

// Figures with their captions, each image a link to itself at full size.
std::string figures_html(const std::vector<std::pair<std::string, std::string>>& figures) {
  std::string s;
  for (const auto& [caption, path] : figures)
    s += fmt::format(
        "<figure><a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\" loading=\"lazy\"></a>"
        "<figcaption>{1} (<a href=\"{0}\">full size</a>)</figcaption></figure>\n",
        html_escape(path), html_escape(caption));
  return s;
}

}  // namespace

std::string gallery_search_text(const GalleryEntry& e) {
  std::string s = e.name + " " + e.material_class + " " + e.kind + " " + e.source;
  for (const auto& k : e.keywords) s += " " + k;
  for (const auto& f : e.flags) s += " " + f;
  return s;
}

std::string gallery_card_html(const GalleryEntry& e) {
  std::string s = fmt::format(
      "<article class=\"card\" id=\"m-{}\" data-search=\"{}\"><h3>{}<span "
      "class=\"cls\">{}</span></h3>"
      "<div class=\"src\">{}</div>",
      html_escape(e.key), html_escape(gallery_search_text(e)), html_escape(e.name),
      html_escape(e.material_class), html_escape(e.source));
  if (!e.strip.empty())
    s += fmt::format(
        "<div class=\"strip\" title=\"ground truth, 0° to 90°\" style=\"background:{}\"></div>"
        "<div class=\"strip-axis\"><span>0°</span><span>45°</span><span>90°</span></div>",
        strip_gradient(e.strip));
  s += fmt::format(
      "<div class=\"sws\"><span class=\"sw\" style=\"background:{}\"></span><span "
      "class=\"swl\">F0</span>"
      "<span class=\"sw\" style=\"background:{}\"></span><span class=\"swl\">F82</span></div>",
      hex(e.f0), hex(e.f82));
  if (!e.flags.empty()) {
    s += "<div class=\"flags\">";
    for (const auto& f : e.flags) s += "<span class=\"flag\">" + html_escape(f) + "</span>";
    s += "</div>";
  }
  if (!e.facts.empty()) {
    s += "<dl class=\"facts\">";
    for (const auto& [label, value] : e.facts)
      s += "<dt>" + html_escape(label) + "</dt><dd>" + html_escape(value) + "</dd>";
    s += "</dl>";
  }
  if (!e.flip.image.empty()) s += flip_html(e.flip);
  if (!e.figures.empty()) {
    s += "<details><summary>figures</summary>";
    for (const auto& [caption, path] : e.figures)
      s += fmt::format(
          "<a href=\"{0}\"><img class=\"fig\" loading=\"lazy\" src=\"{0}\" alt=\"{1}\"></a>"
          "<p class=\"figcap\"><a href=\"{0}\" target=\"_blank\">{1}: open full size</a></p>",
          html_escape(path), html_escape(caption));
    s += "</details>";
  }
  s += "</article>\n";
  return s;
}

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string table_html(const Table& t, const std::string& id, int heading_level) {
  std::string s = fmt::format("<section class=\"table\"><h{0}>{1}</h{0}>\n", heading_level,
                              html_escape(t.title));
  if (!t.reading.empty()) s += "<p>" + inline_markdown(t.reading) + "</p>\n";
  s += fmt::format(
      "<input type=\"search\" placeholder=\"filter rows\" aria-label=\"filter {0}\" "
      "data-table=\"{0}\">"
      "<span class=\"count\">{1} rows</span>\n<div class=\"tablewrap\"><table "
      "id=\"{0}\"><thead><tr>",
      html_escape(id), t.rows.size());
  for (size_t c = 0; c < t.columns.size(); ++c) {
    const bool text = !t.rows.empty() && std::holds_alternative<std::string>(t.rows[0][c]);
    s += fmt::format("<th{}>{}</th>", text ? " class=\"t\"" : "", html_escape(t.columns[c].name));
  }
  s += "</tr></thead><tbody>\n";
  for (const auto& row : t.rows) {
    s += "<tr>";
    for (size_t c = 0; c < row.size(); ++c) s += cell_html(row[c], t.columns[c].precision);
    s += "</tr>\n";
  }
  s += "</tbody></table></div>\n";
  if (!t.notes.empty()) {
    s += "<ul>";
    for (const auto& n : t.notes) s += "<li>" + inline_markdown(n) + "</li>";
    s += "</ul>\n";
  }
  s += "</section>\n";
  return s;
}

std::string gallery_html(const std::vector<GalleryEntry>& entries) {
  std::string s = fmt::format(
      "<input type=\"search\" id=\"gallery-filter\" placeholder=\"search materials, classes, "
      "pages, flags\" "
      "aria-label=\"search the gallery\"><span class=\"count\" id=\"gallery-count\">{0} of {0} "
      "materials</span>\n"
      "<div class=\"gallery\">\n",
      entries.size());
  for (const auto& e : entries) s += gallery_card_html(e);
  s += "</div>\n";
  return s;
}

namespace {

// The tables section; with `folder`, a table larger than kInlineTableBytes is left to a script
// FOLDER/NAME.js (added to `scripts`) that the page loads when the table's section is opened.
std::string tables_section(const HtmlReport& r, const std::string& folder, io::Files* scripts) {
  std::string s = "<section id=\"tables\"><h2>Tables</h2>\n";
  for (const auto& t : r.tables) {
    std::string body = table_html(t, "table-" + t.name, 3);
    if (!folder.empty() && body.size() > kInlineTableBytes) {
      const std::string path = folder + "/" + t.name + ".js", id = "tb-" + t.name;
      scripts->emplace_back(path, "flTable(" + js_string(id) + ", " + js_string(body) + ");\n");
      body = fmt::format("<div id=\"{}\" data-src=\"{}\">loading…</div>", html_escape(id),
                         html_escape(path));
    }
    s += fmt::format(
        "<details class=\"tbl\" id=\"t-{0}\"><summary>{0} <span class=\"sum\">{1} rows</span>"
        "</summary>\n{2}</details>\n",
        html_escape(t.name), t.rows.size(), body);
  }
  return s + "</section>\n";
}

}  // namespace

std::string js_string(const std::string& text) {
  std::string out = "\"";
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"' || c == '\\')
      out += std::string("\\") + c;
    else if (c == '\n')
      out += "\\n";
    else if (c == '/' && i > 0 && text[i - 1] == '<')
      out += "\\/";  // "</script>" must not end the script element
    else if (static_cast<unsigned char>(c) < 0x20)
      out += fmt::format("\\u{:04x}", static_cast<unsigned>(c));
    else
      out += c;
  }
  return out + "\"";
}

std::string html_report(const HtmlReport& r) {
  return html_report_files(r, "").front().second;
}

io::Files html_report_files(const HtmlReport& r, const std::string& folder) {
  io::Files scripts;
  std::string s = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      "<meta name=\"viewport\" content=\"width=device-width, "
      "initial-scale=1\"><title>{}</title><style>{}</style>"
      "</head>\n<body><header><h1>{}</h1>\n",
      html_escape(r.title), kHtmlStyle, html_escape(r.title));
  for (const auto& p : r.intro) s += "<p>" + inline_markdown(p) + "</p>\n";
  s += "<nav>";
  if (!r.summary.empty()) s += "<a href=\"#summary\">Summary</a>";
  s += "<a href=\"#gallery\">Gallery</a>";
  if (!r.lookdev.empty()) s += "<a href=\"#lookdev\">Look-dev</a>";
  s += "<a href=\"#tables\">Tables</a>";
  for (const auto& [text, href] : r.links)
    s += fmt::format("<a href=\"{}\">{}</a>", html_escape(href), html_escape(text));
  s += "</nav></header>\n<main>\n";
  if (!r.summary.empty()) {
    s += "<section id=\"summary\"><h2>Summary</h2><ul>\n";
    for (const auto& line : r.summary) s += "<li>" + inline_markdown(line) + "</li>\n";
    s += "</ul></section>\n";
  }
  if (!r.gallery_fragment.empty() || !r.gallery.empty())
    s += "<section id=\"gallery\"><h2>Gallery</h2>\n" +
         (r.gallery_fragment.empty() ? gallery_html(r.gallery) : r.gallery_fragment) +
         "</section>\n";
  if (!r.figures.empty())
    s += "<section id=\"figures\"><h2>Figures</h2>\n" + figures_html(r.figures) + "</section>\n";
  if (!r.lookdev.empty()) {
    s += "<section id=\"lookdev\"><h2>Look-dev sheets</h2>\n";
    if (!r.lookdev_reading.empty()) s += "<p>" + inline_markdown(r.lookdev_reading) + "</p>\n";
    s += "<div class=\"sheets\">\n" + figures_html(r.lookdev) + "</div></section>\n";
  }
  s += tables_section(r, folder, &scripts);
  s += "</main>\n<script>";
  s += kHtmlScript;
  s += r.gallery_script;
  s += "</script>\n</body></html>\n";
  io::Files out{{"index.html", std::move(s)}};
  for (auto& f : scripts) out.push_back(std::move(f));
  return out;
}

}  // namespace fl::documents
