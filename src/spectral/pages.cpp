#include "spectral/pages.h"

#include <algorithm>
#include <filesystem>
#include <mutex>
#include <optional>
#include <regex>

#include "spectral/yaml_file.h"
#include "util/errors.h"
#include "util/suggest.h"

namespace fl::spectral {
namespace fs = std::filesystem;

std::vector<std::string> list_pages(const std::string& database, const std::string& folder) {
  std::vector<std::string> out;
  const fs::path data = fs::path(database) / "data";
  const fs::path root = folder.empty() ? data : data / folder;
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return out;
  for (auto it = fs::recursive_directory_iterator(
           root, fs::directory_options::skip_permission_denied, ec);
       it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (ec) break;
    const auto& p = it->path();
    if (!it->is_regular_file(ec) || p.extension() != ".yml" || p.filename() == "about.yml")
      continue;
    // The iterator's paths start with `data`: lexical, without resolving each file's path.
    std::string rel = p.lexically_relative(data).generic_string();
    out.push_back(rel.substr(0, rel.size() - 4));
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool glob_match(std::string_view pattern, std::string_view path) {
  if (pattern.empty()) return path.empty();
  if (pattern.substr(0, 2) == "**") {
    for (size_t i = 0; i <= path.size(); ++i)
      if (glob_match(pattern.substr(2), path.substr(i))) return true;
    return false;
  }
  if (pattern[0] == '*') {
    for (size_t i = 0; i <= path.size(); ++i) {
      if (glob_match(pattern.substr(1), path.substr(i))) return true;
      if (i < path.size() && path[i] == '/') break;
    }
    return false;
  }
  if (path.empty()) return false;
  if (pattern[0] == '?' ? path[0] == '/' : pattern[0] != path[0]) return false;
  return glob_match(pattern.substr(1), path.substr(1));
}

std::string glob_folder(std::string_view pattern) {
  const size_t wild = pattern.find_first_of("*?");
  const size_t slash = pattern.substr(0, wild).rfind('/');
  if (slash == std::string_view::npos) return {};
  const fs::path folder(pattern.substr(0, slash));
  // A folder outside data/ holds no page: the whole listing is matched (and matches nothing).
  if (folder.is_absolute() ||
      std::find(folder.begin(), folder.end(), fs::path("..")) != folder.end())
    return {};
  return folder.generic_string();
}

bool is_glob(std::string_view spec) {
  return spec.find_first_of("*?") != std::string_view::npos;
}

std::vector<std::string> match_pages(const std::vector<std::string>& pages,
                                     const std::string& pattern) {
  std::vector<std::string> out;
  for (const auto& p : pages)
    if (glob_match(pattern, p)) out.push_back(p);
  return out;
}

std::string book_of(const std::string& page) {
  const fs::path folder = fs::path(page).parent_path();
  const fs::path above = folder.parent_path();
  return (above.empty() ? folder : above).filename().string();
}

namespace {

std::string text(const YamlNode& n, const char* key) {
  return n[key].scalar();
}

void add_book(const YamlNode& book, std::map<std::string, PageEntry>& out) {
  const YamlNode& content = book["content"];
  if (!content.is_sequence()) return;
  std::string section;
  for (const auto& item : content.items()) {
    if (!item.is_map()) continue;
    if (item["DIVIDER"]) section = text(item, "DIVIDER");
    if (!item["PAGE"]) continue;
    std::string data = text(item, "data");
    if (data.size() < 4 || data.substr(data.size() - 4) != ".yml") continue;
    data.resize(data.size() - 4);
    out.emplace(data, PageEntry{book_of(data), text(book, "name"), text(item, "name"), section});
  }
}

}  // namespace

// The 480 KB catalog takes libyaml about 5 ms.
std::map<std::string, PageEntry> read_page_catalog(const std::string& database) {
  std::map<std::string, PageEntry> out;
  const std::string path = database + "/catalog-nk.yml";
  std::error_code ec;
  if (!fs::exists(path, ec)) return out;
  const YamlNode root = read_yaml_file(path);  // a directory, empty, binary, invalid YAML: throws
  if (!root.is_sequence()) throw InputError(path, 1, "expected a list of shelves");
  for (const auto& shelf : root.items()) {
    if (!shelf.is_map() || !shelf["content"].is_sequence()) continue;
    for (const auto& book : shelf["content"].items())
      if (book.is_map() && book["BOOK"]) add_book(book, out);
  }
  return out;
}

const std::map<std::string, PageEntry>& PageCatalog::entries() const {
  // call_once leaves the flag unset when the read throws: the next use reads (and throws) again.
  std::call_once(read_, [this] { entries_ = read_page_catalog(database_); });
  return entries_;
}

const PageEntry* PageCatalog::find(const std::string& page) const {
  const auto& all = entries();
  const auto e = all.find(page);
  return e == all.end() ? nullptr : &e->second;
}

const char* to_string(PageKind kind) {
  switch (kind) {
    case PageKind::Bulk:
      return "bulk";
    case PageKind::ThinFilm:
      return "thin film";
    case PageKind::Nanostructure:
      return "nanostructure";
    case PageKind::Model:
      return "model";
    case PageKind::Computed:
      return "computed";
    case PageKind::Variant:
      return "variant";
    case PageKind::Unlisted:
      return "unlisted";
  }
  return "unlisted";
}

namespace {

bool has_any(const std::string& s, std::initializer_list<const char*> words) {
  for (const char* w : words)
    if (s.find(w) != std::string::npos) return true;
  return false;
}

std::string first_match(const std::string& s, const std::regex& re, int group = 0) {
  std::smatch m;
  return std::regex_search(s, m, re) ? m[group].str() : std::string();
}

// A temperature in the page name ("298 K", "225 °C"), with whether it is room temperature.
std::optional<std::pair<std::string, bool>> temperature(const std::string& name) {
  static const std::regex re(
      "(\\d+(?:\\.\\d+)?) ?(K|\xC2\xB0"
      "C)(?![A-Za-z])");
  std::smatch m;
  if (!std::regex_search(name, m, re)) return std::nullopt;
  const double value = std::stod(m[1].str());
  const double kelvin = m[2].str() == "K" ? value : value + 273.15;
  return std::make_pair(m[0].str(), kelvin >= 288.0 && kelvin <= 303.0);
}

}  // namespace

PageClass classify_page(const PageEntry* entry) {
  PageClass c;
  if (!entry) return c;
  // A year is four digits that are not part of a decimal number ("0.2066" is no year).
  static const std::regex year_re("(?:^|[^0-9.])((?:19|20)\\d\\d)(?![0-9])");
  static const std::regex thickness_re("(\\d+(?:\\.\\d+)?)[- ]?nm film");
  static const std::regex radius_re("R ?= ?\\d+(?:\\.\\d+)? ?nm");
  static const std::regex pressure_re("\\d ?(GPa|MPa|kbar)(?![A-Za-z])");
  const std::string year = first_match(entry->page_name, year_re, 1);
  c.year = year.empty() ? 0 : std::stoi(year);
  const std::string both = ascii_lower(entry->section + " | " + entry->page_name);
  const std::string thickness = first_match(entry->page_name, thickness_re, 1);
  if (has_any(both, {"dft", "ab initio", "first-principles", "calculation", "computed"})) {
    c.kind = PageKind::Computed;
  } else if (has_any(both, {"model", "simulation"})) {
    c.kind = PageKind::Model;
  } else if (has_any(both, {"nanoparticle", "island", "flake", "2d structure"})) {
    c.kind = PageKind::Nanostructure;
    c.detail = first_match(entry->page_name, radius_re);
  } else if (both.find("thin film") != std::string::npos || !thickness.empty()) {
    c.kind = PageKind::ThinFilm;
    c.detail = thickness.empty() ? std::string() : thickness + " nm";
  } else if (const auto t = temperature(entry->page_name)) {
    c.kind = t->second ? PageKind::Bulk : PageKind::Variant;
    c.detail = t->first;
  } else if (std::regex_search(entry->page_name, pressure_re)) {
    c.kind = PageKind::Variant;
  } else {
    c.kind = PageKind::Bulk;
  }
  return c;
}

bool is_bulk_measurement(const PageEntry* entry) {
  return classify_page(entry).kind == PageKind::Bulk;
}

}  // namespace fl::spectral
