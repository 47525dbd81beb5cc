#include "spectral/material.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include "spectral/nk_text.h"
#include "spectral/pages.h"
#include "spectral/text_file.h"
#include "spectral/yaml_file.h"
#include "util/errors.h"
#include "util/parallel.h"
#include "util/suggest.h"

namespace fl::spectral {
namespace fs = std::filesystem;

const char* to_string(MaterialClass c) {
  return c == MaterialClass::Metal ? "metal" : "dielectric";
}

MaterialClass classify(const OpticalConstants& oc) {
  // Sampled on the whole visible grid so that a range error names 360-830 nm.
  const SpectralGrid g = SpectralGrid::visible(5.0);
  const auto s = sample_ior(oc, g, oc.file);
  double k = 0;
  int count = 0;
  for (int i = 0; i < g.count; ++i) {
    if (g.lambda_nm(i) < 400.0 || g.lambda_nm(i) > 700.0) continue;
    k += s.ior.ior[i].imag();
    ++count;
  }
  return k / count > kMetalMinK ? MaterialClass::Metal : MaterialClass::Dielectric;
}

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string scalar(const YamlNode& root, const char* key, const std::string& path, bool required) {
  const YamlNode& n = root[key];
  if (!n) {
    if (required) throw InputError(path, 0, fmt::format("missing field '{}'", key));
    return {};
  }
  if (!n.is_scalar())
    throw InputError(path, n.line() + 1, fmt::format("field '{}' must be a string", key));
  return n.scalar();
}

// InputError at the first key of `map` that is not one of `known`, with the nearest known key
// when one is close.
void require_known_keys(const YamlNode& map, const std::vector<std::string>& known,
                        const std::string& path, const std::string& where) {
  for (const auto& [key, value] : map.fields()) {
    const std::string name = key.is_scalar() ? key.scalar() : std::string();
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    const std::string hint = did_you_mean(name, known);
    throw InputError(
        path, key.line() + 1,
        fmt::format("unknown key '{}' in {}{}", key.is_scalar() ? name : "(a list or map)", where,
                    hint.empty() ? " (expected " + join(known) + ")" : hint));
  }
}

// The keys a catalog entry may have; any other is an InputError at its line, suggesting the nearest
// of these when one is close (a misspelt optional key would otherwise be silently ignored).
const std::vector<std::string> kEntryKeys{"name",      "class", "aliases",
                                          "reference", "order", "talk_schlick_rms_de00",
                                          "source",    "file",  "constant"};

// An entry's `aliases`: a list of names (or one name), each a non-empty string.
std::vector<std::string> entry_aliases(const YamlNode& root, const std::string& path) {
  const YamlNode& n = root["aliases"];
  if (!n) return {};
  if (n.is_scalar()) return {n.scalar()};
  std::vector<std::string> out;
  if (n.is_sequence())
    for (const auto& item : n.items())
      if (item.is_scalar() && !item.scalar().empty()) out.push_back(item.scalar());
  if (!n.is_sequence() || out.size() != n.items().size())
    throw InputError(path, n.line() + 1, "field 'aliases' must be a list of names");
  return out;
}

}  // namespace

namespace {

// The catalog's entry files (*.yml, *.yaml), sorted; InputError when the folder is missing or
// cannot be listed.
std::vector<std::string> catalog_files(const std::string& folder) {
  std::vector<std::string> files;
  for (auto& f : list_folder(folder, "material catalog folder")) {
    const auto ext = fs::path(f).extension();
    if (ext == ".yml" || ext == ".yaml") files.push_back(std::move(f));
  }
  return files;
}

}  // namespace

void require_unique_names(const std::vector<std::string>& files, const std::vector<Material>& ms) {
  std::map<std::string, size_t> keys, names;
  for (size_t i = 0; i < ms.size(); ++i) {
    if (const auto [it, added] = keys.emplace(ascii_lower(ms[i].key), i); !added)
      throw InputError(files[i], 0,
                       fmt::format("catalog key '{}' is also the key of {} (keys are compared "
                                   "ignoring case)",
                                   ms[i].key, files[it->second]));
    for (const auto& alias : ms[i].aliases)
      if (const auto [it, added] = names.emplace(ascii_lower(alias), i); !added)
        throw InputError(files[i], 0,
                         fmt::format("alias '{}' already names {} (names and aliases are compared "
                                     "ignoring case)",
                                     alias, files[it->second]));
    if (const auto [it, added] = names.emplace(ascii_lower(ms[i].name), i); !added) {
      const auto line = [](const std::string& f) { return read_yaml_file(f)["name"].line() + 1; };
      throw InputError(files[i], line(files[i]),
                       fmt::format("name '{}' is already the name of {}:{} (names are compared "
                                   "ignoring case)",
                                   ms[i].name, files[it->second], line(files[it->second])));
    }
  }
}

namespace {

// A catalog entry's optional numbers: 'order' and the talk's Schlick error.
void read_entry_numbers(const YamlNode& root, const std::string& path, Material& m) {
  for (const char* key : {"order", "talk_schlick_rms_de00"}) {
    const std::string v = scalar(root, key, path, false);
    double x = 0;
    if (v.empty()) continue;
    if (!parse_finite(v, x))
      throw InputError(path, root[key].line() + 1, fmt::format("field '{}' must be a number", key));
    if (std::string(key) == "order") {
      if (x != std::floor(x) || std::abs(x) > 1e6)
        throw InputError(path, root[key].line() + 1,
                         "field 'order' must be an integer between -1000000 and 1000000");
      m.order = static_cast<int>(x);
    } else
      m.talk_schlick_rms_de00 = x;
  }
}

// A catalog entry's data: a database page ('source'), a file, or a constant index.
void read_entry_data(const YamlNode& root, const std::string& path, const DataPaths& paths,
                     Material& m) {
  const std::string page = scalar(root, "source", path, false);
  const std::string file = scalar(root, "file", path, false);
  if (!page.empty() && !file.empty())
    throw InputError(path, root["file"].line() + 1,
                     "give either 'source' (a database page) or 'file', not both");
  if (!page.empty()) {
    m.source = page;
    m.constants = read_refractiveindex_file(database_file(paths, page));
    m.page_class = classify_page(page_catalog(paths)->find(page));
  } else if (!file.empty()) {
    const fs::path f =
        fs::path(file).is_absolute() ? fs::path(file) : fs::path(path).parent_path() / file;
    m.source = file;
    m.constants = read_optical_file(f.string());
  } else if (const YamlNode& c = root["constant"]) {
    double n = 0, k = 0;
    try {
      if (!c.is_map() || !c["n"])
        throw InputError(path, c.line() + 1, "'constant' needs n (and optional k)");
      require_known_keys(c, {"n", "k"}, path, "'constant'");
      if (!parse_finite(c["n"].as_string(), n) || (c["k"] && !parse_finite(c["k"].as_string(), k)))
        throw InputError(path, c.line() + 1, "'constant' n and k must be finite numbers");
    } catch (const YamlError& e) {
      throw InputError(path, e.line + 1, std::string("malformed 'constant': ") + e.what());
    }
    m.source = k == 0 ? fmt::format("constant n={}", n) : fmt::format("constant n={} k={}", n, k);
    m.constants = constant_ior(n, k, path);
  } else {
    throw InputError(path, 0, "needs 'source' (a database page), 'file' or 'constant'");
  }
}

}  // namespace

Material read_catalog_entry(const std::string& path, const DataPaths& paths) {
  const YamlNode root = read_yaml_file(path);
  if (!root.is_map()) throw InputError(path, 1, "a catalog entry must be a YAML map");
  require_known_keys(root, kEntryKeys, path, "a catalog entry");
  Material m;
  m.key = fs::path(path).stem().string();
  m.name = scalar(root, "name", path, true);
  m.aliases = entry_aliases(root, path);
  const std::string cls = scalar(root, "class", path, true);
  if (cls == "metal")
    m.material_class = MaterialClass::Metal;
  else if (cls == "dielectric")
    m.material_class = MaterialClass::Dielectric;
  else
    throw InputError(path, root["class"].line() + 1,
                     fmt::format("class '{}' must be metal or dielectric", cls));
  m.reference = scalar(root, "reference", path, false);
  read_entry_numbers(root, path, m);
  read_entry_data(root, path, paths, m);
  return m;
}

std::vector<Material> read_catalog(const DataPaths& paths) {
  const std::vector<std::string> files = catalog_files(paths.materials);
  // Read concurrently; the first broken entry in file order is the one reported.
  std::vector<Material> out(files.size());
  parallel_for_all(files.size(), [&](size_t i) { out[i] = read_catalog_entry(files[i], paths); });
  require_unique_names(files, out);
  std::stable_sort(out.begin(), out.end(),
                   [](const Material& a, const Material& b) { return a.order < b.order; });
  return out;
}

std::string database_file(const DataPaths& paths, const std::string& page) {
  return paths.database + "/data/" + page + ".yml";
}

CatalogIndex read_catalog_index(const std::string& folder) {
  CatalogIndex index;
  index.folder = folder;
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return index;
  for (const auto& f : catalog_files(folder)) {
    CatalogIndex::Entry e{f, {fs::path(f).stem().string()}, {}};
    try {
      const YamlNode root = read_yaml_file(f);
      if (root.is_map() && root["name"] && root["name"].is_scalar())
        e.names.push_back(root["name"].scalar());
      if (root.is_map()) {
        const auto aliases = entry_aliases(root, f);
        e.names.insert(e.names.end(), aliases.begin(), aliases.end());
      }
    } catch (const YamlError& err) {
      e.error = err.what();
    } catch (const InputError& err) {
      e.error = err.what();
    }
    index.entries.push_back(std::move(e));
  }
  return index;
}

std::shared_ptr<const CatalogIndex> catalog_index(const DataPaths& paths) {
  if (paths.catalog && paths.catalog->folder == paths.materials) return paths.catalog;
  return std::make_shared<const CatalogIndex>(read_catalog_index(paths.materials));
}

std::string unreadable_entries(const DataPaths& paths) {
  std::string out;
  const auto index = catalog_index(paths);
  for (const auto& e : index->entries)
    if (!e.error.empty()) out += (out.empty() ? "; unreadable catalog entries: " : "; ") + e.error;
  return out;
}

}  // namespace fl::spectral
