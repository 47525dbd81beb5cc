#include "spectral/pages.h"

#include <yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>

namespace fl::spectral {
namespace fs = std::filesystem;

std::vector<std::string> list_pages(const std::string& database, const std::string& folder) {
  std::vector<std::string> out;
  const fs::path data = fs::path(database) / "data";
  const fs::path root = folder.empty() ? data : data / folder;
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return out;
  for (auto it = fs::recursive_directory_iterator(root, fs::directory_options::skip_permission_denied, ec);
       it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (ec) break;
    const auto& p = it->path();
    if (!it->is_regular_file(ec) || p.extension() != ".yml" || p.filename() == "about.yml") continue;
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
  if (folder.is_absolute() || std::find(folder.begin(), folder.end(), fs::path("..")) != folder.end()) return {};
  return folder.generic_string();
}

bool is_glob(std::string_view spec) { return spec.find_first_of("*?") != std::string_view::npos; }

std::vector<std::string> match_pages(const std::vector<std::string>& pages, const std::string& pattern) {
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

// The catalog as a small tree read with libyaml's event parser: the 480 KB catalog-nk.yml takes
// libyaml about 5 ms where yaml-cpp's node tree takes about 95 ms (the pages and the user's YAML
// files stay with yaml-cpp, read_yaml_file). Only what the catalog holds is kept: mappings,
// sequences and scalars (an empty or ~/null plain scalar is a null, as in yaml-cpp).
struct CatalogNode {
  enum class Kind { Null, Scalar, Sequence, Map } kind = Kind::Null;
  std::string scalar;
  std::vector<CatalogNode> items;                           // Sequence
  std::vector<std::pair<std::string, CatalogNode>> fields;  // Map, in file order

  const CatalogNode* find(std::string_view key) const {
    for (const auto& [k, v] : fields)
      if (k == key) return &v;
    return nullptr;
  }
  std::string text(std::string_view key) const {
    const CatalogNode* v = find(key);
    return v && v->kind == Kind::Scalar ? v->scalar : std::string();
  }
};

class CatalogParser {
 public:
  explicit CatalogParser(const std::string& text) {
    yaml_parser_initialize(&parser_);
    yaml_parser_set_input_string(&parser_, reinterpret_cast<const unsigned char*>(text.data()), text.size());
  }
  ~CatalogParser() { yaml_parser_delete(&parser_); }
  CatalogParser(const CatalogParser&) = delete;
  CatalogParser& operator=(const CatalogParser&) = delete;

  // The first document's root; false on a syntax error or an empty stream.
  bool root(CatalogNode& out) {
    for (;;) {
      if (!next()) return false;
      const auto type = event_.type;
      if (type == YAML_STREAM_END_EVENT) return false;
      if (type != YAML_STREAM_START_EVENT && type != YAML_DOCUMENT_START_EVENT) return node(out);
    }
  }

 private:
  bool next() {
    if (have_event_) yaml_event_delete(&event_);
    have_event_ = yaml_parser_parse(&parser_, &event_) != 0;
    return have_event_;
  }
  // The node whose first event is the current one.
  bool node(CatalogNode& out) {
    switch (event_.type) {
      case YAML_SCALAR_EVENT: {
        const auto& s = event_.data.scalar;
        out.scalar.assign(reinterpret_cast<const char*>(s.value), s.length);
        const bool plain = s.style == YAML_PLAIN_SCALAR_STYLE;
        const bool null = plain && (out.scalar.empty() || out.scalar == "~" || out.scalar == "null" ||
                                    out.scalar == "Null" || out.scalar == "NULL");
        out.kind = null ? CatalogNode::Kind::Null : CatalogNode::Kind::Scalar;
        return true;
      }
      case YAML_SEQUENCE_START_EVENT:
        out.kind = CatalogNode::Kind::Sequence;
        for (;;) {
          if (!next()) return false;
          if (event_.type == YAML_SEQUENCE_END_EVENT) return true;
          if (!node(out.items.emplace_back())) return false;
        }
      case YAML_MAPPING_START_EVENT:
        out.kind = CatalogNode::Kind::Map;
        for (;;) {
          if (!next()) return false;
          if (event_.type == YAML_MAPPING_END_EVENT) return true;
          CatalogNode key;
          if (!node(key) || !next()) return false;
          auto& field = out.fields.emplace_back(std::move(key.scalar), CatalogNode{});
          if (!node(field.second)) return false;
        }
      default:  // an alias: the catalog has none, and a null stands in for one
        return true;
    }
  }

  yaml_parser_t parser_{};
  yaml_event_t event_{};
  bool have_event_ = false;
};

void add_book(const CatalogNode& book, std::map<std::string, PageEntry>& out) {
  const CatalogNode* content = book.find("content");
  if (!content || content->kind != CatalogNode::Kind::Sequence) return;
  std::string section;
  for (const auto& item : content->items) {
    if (item.kind != CatalogNode::Kind::Map) continue;
    if (item.find("DIVIDER")) section = item.text("DIVIDER");
    if (!item.find("PAGE")) continue;
    std::string data = item.text("data");
    if (data.size() < 4 || data.substr(data.size() - 4) != ".yml") continue;
    data.resize(data.size() - 4);
    out.emplace(data, PageEntry{book_of(data), book.text("name"), item.text("name"), section});
  }
}

}  // namespace

std::map<std::string, PageEntry> read_page_catalog(const std::string& database) {
  std::map<std::string, PageEntry> out;
  std::ifstream file(database + "/catalog-nk.yml", std::ios::binary);
  if (!file) return out;
  const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  CatalogNode root;
  if (!CatalogParser(text).root(root) || root.kind != CatalogNode::Kind::Sequence) return out;
  for (const auto& shelf : root.items) {
    const CatalogNode* books = shelf.kind == CatalogNode::Kind::Map ? shelf.find("content") : nullptr;
    if (!books || books->kind != CatalogNode::Kind::Sequence) continue;
    for (const auto& book : books->items)
      if (book.kind == CatalogNode::Kind::Map && book.find("BOOK")) add_book(book, out);
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
