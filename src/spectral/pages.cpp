#include "spectral/pages.h"

#include <algorithm>
#include <filesystem>
#include <mutex>

#include "spectral/errors.h"
#include "spectral/yaml_file.h"

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

// An unreadable or broken catalog names nothing (InputError from read_yaml_file: missing, empty,
// binary or invalid YAML). The 480 KB catalog takes libyaml about 5 ms, where yaml-cpp took 95.
std::map<std::string, PageEntry> read_page_catalog(const std::string& database) {
  std::map<std::string, PageEntry> out;
  try {
    const YamlNode root = read_yaml_file(database + "/catalog-nk.yml");
    if (!root.is_sequence()) return out;
    for (const auto& shelf : root.items()) {
      if (!shelf.is_map() || !shelf["content"].is_sequence()) continue;
      for (const auto& book : shelf["content"].items())
        if (book.is_map() && book["BOOK"]) add_book(book, out);
    }
  } catch (const InputError&) {
    out.clear();
  }
  return out;
}

const PageEntry* page_entry(const std::string& database, const std::string& page) {
  static std::mutex mutex;
  static std::map<std::string, std::map<std::string, PageEntry>> catalogs;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = catalogs.find(database);
  if (it == catalogs.end()) it = catalogs.emplace(database, read_page_catalog(database)).first;
  const auto e = it->second.find(page);
  return e == it->second.end() ? nullptr : &e->second;
}

bool is_bulk_measurement(const PageEntry* entry) {
  if (!entry) return false;
  std::string s = entry->section;
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const char* word : {"model", "simulation", "thin film", "nanoparticle", "flake", "2d"})
    if (s.find(word) != std::string::npos) return false;
  return true;
}

}  // namespace fl::spectral
