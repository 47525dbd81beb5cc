#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include "spectral/material.h"
#include "spectral/nk_text.h"
#include "spectral/pages.h"
#include "spectral/text_file.h"
#include "spectral/yaml_file.h"
#include "util/errors.h"
#include "util/parallel.h"
#include "util/suggest.h"

namespace fl::spectral {
namespace fs = std::filesystem;

namespace {

// `folder`'s entry spelled `name` ignoring ASCII case ("AU" finds "Au"), if any.
std::optional<std::string> entry_ignoring_case(const std::string& folder, const std::string& name) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec))
    if (ascii_lower(e.path().filename().string()) == ascii_lower(name))
      return e.path().filename().string();
  return std::nullopt;
}

// The catalog entries one of whose names has `word` as a whole word ("glass" in "glass_bk7"), as
// " (did you mean one of 'a', 'b'?)", or "" when none has.
std::string entries_with_word(const std::string& word,
                              const std::vector<std::vector<std::string>>& entries) {
  std::vector<std::string> found;
  const std::string want = ascii_lower(word);
  for (const auto& names : entries)
    for (const auto& n : names) {
      std::string folded = ascii_lower(n);
      for (char& c : folded) c = c == '-' || c == ' ' ? '_' : c;
      if (folded.rfind(want + "_", 0) == 0 || folded.ends_with("_" + want) ||
          folded.find("_" + want + "_") != std::string::npos) {
        found.push_back(names.front());
        break;
      }
    }
  if (found.empty()) return "";
  std::string list;
  for (const auto& f : found) list += (list.empty() ? "'" : ", '") + f + "'";
  return " (did you mean one of " + list + "?)";
}

// " (did you mean 'X'?)" for an unknown material: the catalog entries with the word in their names
// ("glass"), else the nearest catalog name, or for a page path the nearest page on the same shelf
// and book, whose folders may be typed in any case ("main/AU/nk/Johnson", "main/Au/Johnson").
std::string material_hint(const std::string& spec, const DataPaths& paths) {
  std::vector<std::string> candidates;
  std::error_code ec;
  if (spec.find('/') == std::string::npos) {
    if (!fs::is_directory(paths.materials, ec)) return "";
    std::vector<std::vector<std::string>> entries;
    const auto index = catalog_index(paths);
    for (const auto& e : index->entries) {
      candidates.insert(candidates.end(), e.names.begin(), e.names.end());
      entries.push_back(e.names);
    }
    if (auto word = entries_with_word(spec, entries); !word.empty()) return word;
  } else {
    const auto first = spec.find('/'), second = spec.find('/', first + 1);
    const auto shelf = entry_ignoring_case(paths.database + "/data", spec.substr(0, first));
    const auto book = shelf ? entry_ignoring_case(paths.database + "/data/" + *shelf,
                                                  spec.substr(first + 1, second - first - 1))
                            : std::nullopt;
    if (book) candidates = list_pages(paths.database, *shelf + "/" + *book);
  }
  return did_you_mean(spec, candidates);
}

// The catalog entry whose key, display name or alias is `spec` (ignoring case), if any.
std::optional<Material> find_in_catalog(const std::string& spec, const DataPaths& paths) {
  std::error_code ec;
  if (!fs::is_directory(paths.materials, ec)) return std::nullopt;
  const std::string want = ascii_lower(spec);
  std::vector<std::string> named;
  const auto index = catalog_index(paths);
  for (const auto& e : index->entries)
    if (std::any_of(e.names.begin(), e.names.end(),
                    [&](const std::string& n) { return ascii_lower(n) == want; }))
      named.push_back(e.file);
  if (named.size() > 1) {
    std::vector<Material> ms;
    for (const auto& f : named) ms.push_back(read_catalog_entry(f, paths));
    require_unique_names(named, ms);
  }
  if (named.empty()) return std::nullopt;
  return read_catalog_entry(named.front(), paths);
}

// A material file: a catalog entry, a refractiveindex.info page or a table of optical constants.
Material read_material_file(const std::string& spec, const DataPaths& paths) {
  Material m;
  m.origin = Material::Origin::File;
  m.name = fs::path(spec).stem().string();
  if (ascii_lower(fs::path(spec).extension().string()) ==
      ".spd")  // NAME.eta.spd or NAME.k.spd: NAME
    m.name = fs::path(m.name).stem().string();
  m.key = m.name;
  m.file = spec;
  m.source = fs::path(spec).is_absolute() ? fs::path(spec).filename().string() : spec;
  const auto ext = ascii_lower(fs::path(spec).extension().string());
  if (ext == ".yml" || ext == ".yaml") {
    // A catalog entry has 'class'; a database file has 'DATA'.
    const YamlNode root = read_yaml_file(spec);
    if (root.is_map() && root["class"] && !root["DATA"]) return read_catalog_entry(spec, paths);
  }
  m.constants = read_optical_file(spec);
  m.material_class = classify(m.constants);
  return m;
}

}  // namespace

Material resolve_material(const std::string& spec, const DataPaths& paths) {
  if (spec.empty()) throw InputError("empty material name");
  // A catalog key, display name or alias.
  if (auto m = find_in_catalog(spec, paths)) return *std::move(m);
  // A file path.
  std::error_code ec;
  if (fs::exists(spec, ec)) return read_material_file(spec, paths);
  // A database page.
  const std::string page = spec.size() > 4 && spec.substr(spec.size() - 4) == ".yml"
                               ? spec.substr(0, spec.size() - 4)
                               : spec;
  if (page.find('/') != std::string::npos && fs::exists(database_file(paths, page), ec))
    return read_database_page(page, paths);
  if (const auto ext = ascii_lower(fs::path(spec).extension().string());
      ext == ".csv" || ext == ".yml" || ext == ".yaml" || ext == ".txt" || ext == ".tsv" ||
      ext == ".nk" || ext == ".mat" || ext == ".dat" || ext == ".spd")
    throw InputError(
        spec, 0,
        fmt::format("no such file (nor a catalog name in {} or a database page under {}/data)",
                    paths.materials, paths.database));
  throw InputError(fmt::format(
      "unknown material '{}'{}: not a catalog name in {}, a file, or a database page under "
      "{}/data{}",
      spec, material_hint(spec, paths), paths.materials, paths.database,
      unreadable_entries(paths)));
}

std::shared_ptr<const PageCatalog> page_catalog(const DataPaths& paths) {
  return paths.pages ? paths.pages : std::make_shared<const PageCatalog>(paths.database);
}

Material read_database_page(const std::string& page, const DataPaths& paths) {
  Material m;
  m.origin = Material::Origin::Page;
  m.key = page;
  m.name = page;
  m.source = page;
  m.constants = read_refractiveindex_file(database_file(paths, page));
  m.reference = m.constants.reference;
  m.material_class = classify(m.constants);
  const auto pages = page_catalog(paths);
  const PageEntry* entry = pages->find(page);
  if (entry) m.book_name = entry->book_name, m.section = entry->section;
  m.page_class = classify_page(entry);
  m.bulk_measurement = m.page_class.kind == PageKind::Bulk;
  return m;
}

std::vector<MaterialRequest> expand_materials(const std::vector<std::string>& specs,
                                              const DataPaths& paths) {
  std::vector<MaterialRequest> out;
  std::map<std::string, std::vector<std::string>>
      pages;  // by folder: only what the globs can match is listed
  for (const auto& spec : specs) {
    if (!is_glob(spec)) {
      out.push_back({spec, ""});
      continue;
    }
    const std::string folder = glob_folder(spec);
    auto listed = pages.find(folder);
    if (listed == pages.end())
      listed = pages.emplace(folder, list_pages(paths.database, folder)).first;
    const auto matched = match_pages(listed->second, spec);
    if (matched.empty())
      throw InputError(
          fmt::format("'{}' matches no database page under {}/data", spec, paths.database));
    for (const auto& p : matched) out.push_back({p, spec});
  }
  return out;
}

}  // namespace fl::spectral
