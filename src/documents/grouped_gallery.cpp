#include "documents/grouped_gallery.h"

#include <fmt/format.h>

#include <map>

#include "util/suggest.h"

namespace fl::documents {
namespace {

// The page's side: the search over the index, and loading a group's script when its place comes
// within 800 px of the screen or the search matches one of its cards.
constexpr const char* kGroupedScript = R"JS(
(function () {
  'use strict';
  var holder = document.getElementById('gallery-index');
  if (!holder) return;
  var index = JSON.parse(holder.textContent), input = document.getElementById('gallery-filter');
  var count = document.getElementById('gallery-count'), requested = {};
  // Each term must begin a word ("au" finds "main/Au/…", not "Tamosauskas").
  function terms(query) {
    return query.toLowerCase().split(/\s+/).filter(Boolean).map(function (t) {
      return new RegExp('(^|[^a-z0-9])' + t.replace(/[.*+?^${}()|[\]\\]/g, '\\$&'));
    });
  }
  function matches(text, res) {
    text = text.toLowerCase();
    return res.every(function (r) { return r.test(text); });
  }
  function load(box) {
    var src = box.getAttribute('data-src');
    if (!src || requested[src]) return;
    requested[src] = true;
    var s = document.createElement('script');
    s.src = src;
    document.body.appendChild(s);
  }
  // A group one of whose keywords is the whole query (an element's symbol or name) comes first.
  function apply() {
    var q = input.value, res = terms(q), exact = q.trim().toLowerCase(), found = {}, groups = {};
    var first = {}, shown = 0;
    index.forEach(function (e) {
      if (!matches(e[2], res)) return;
      found[e[0]] = true;
      groups[e[1]] = true;
      shown++;
      if (exact && e[3].indexOf(exact) >= 0) first[e[1]] = true;
    });
    document.querySelectorAll('.group').forEach(function (g) {
      g.style.order = first[g.getAttribute('data-group')] ? '-1' : '';
      g.hidden = !groups[g.getAttribute('data-group')];
      var box = g.querySelector('.gallery[data-src]');
      if (box && q && !g.hidden) load(box);
    });
    document.querySelectorAll('.group .card').forEach(function (c) { c.hidden = !found[c.id]; });
    count.textContent = shown + ' of ' + index.length + ' materials';
  }
  window.flGalleryCards = function (group, html) {
    var section = Array.prototype.find.call(document.querySelectorAll('.group'), function (g) {
      return g.getAttribute('data-group') === group;
    });
    var box = section.querySelector('.gallery');
    box.innerHTML = html;
    box.removeAttribute('data-src');
    apply();
  };
  var seen = new IntersectionObserver(function (entries) {
    entries.forEach(function (e) {
      if (e.isIntersecting) { seen.unobserve(e.target); load(e.target); }
    });
  }, { rootMargin: '800px 0px' });
  document.querySelectorAll('.gallery[data-src]').forEach(function (b) { seen.observe(b); });
  input.addEventListener('input', apply);
})();
)JS";

// Per entry [card id, group, gallery_search_text, [keywords in lower case]], as JSON.
std::string search_index(const std::vector<GalleryEntry>& entries) {
  std::string index = "[";
  for (const auto& e : entries) {
    std::string keywords = "[";
    for (const auto& k : e.keywords)
      keywords += (keywords.size() > 1 ? "," : "") + js_string(ascii_lower(k));
    index += (index.size() > 1 ? ",\n" : "") +
             fmt::format("[{},{},{},{}]", js_string("m-" + e.key), js_string(e.group),
                         js_string(gallery_search_text(e)), keywords + "]");
  }
  return index + "]";
}

}  // namespace

GroupedGallery grouped_gallery(const std::vector<GalleryEntry>& entries, size_t eager_cards,
                               const std::string& folder) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<const GalleryEntry*>> groups;
  for (const auto& e : entries) {
    if (!groups.count(e.group)) order.push_back(e.group);
    groups[e.group].push_back(&e);
  }
  GroupedGallery out;
  out.html = fmt::format(
      "<input type=\"search\" id=\"gallery-filter\" placeholder=\"search elements, names, "
      "pages, kinds, flags\" aria-label=\"search the gallery\"><span class=\"count\" "
      "id=\"gallery-count\">{0} of {0} materials</span>\n"
      "<script type=\"application/json\" id=\"gallery-index\">{1}</script>\n<div id=\"groups\">\n",
      entries.size(), search_index(entries));
  size_t set = 0;
  for (size_t g = 0; g < order.size(); ++g) {
    const auto& cards = groups[order[g]];
    std::string html;
    for (const auto* e : cards) html += gallery_card_html(*e);
    out.html += fmt::format(
        "<section class=\"group\" data-group=\"{0}\"><h3>{0} <span class=\"count\">{1} {2}</span>"
        "</h3>\n",
        html_escape(order[g]), cards.size(), cards.size() == 1 ? "entry" : "entries");
    if (set < eager_cards) {
      out.html += "<div class=\"gallery\">\n" + html + "</div></section>\n";
      set += cards.size();
      continue;
    }
    const std::string path = fmt::format("{}/{:03d}.js", folder, g + 1);
    out.html +=
        fmt::format("<div class=\"gallery\" data-src=\"{}\"></div></section>\n", html_escape(path));
    out.files.emplace_back(
        path, fmt::format("flGalleryCards({}, {});\n", js_string(order[g]), js_string(html)));
  }
  out.html += "</div>\n";
  out.script = kGroupedScript;
  return out;
}

}  // namespace fl::documents
