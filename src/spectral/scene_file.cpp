#include "spectral/scene_file.h"

#include <fmt/format.h>

#include <algorithm>

#include "spectral/text_file.h"
#include "spectral/yaml_file.h"
#include "util/errors.h"
#include "util/suggest.h"
#include "util/truncated.h"

namespace fl::spectral {
namespace {

// " (did you mean 'X'?)" when a known name is close, else " (expected A, B, C)".
std::string hint_or_list(const std::string& name, const std::vector<std::string>& known) {
  const std::string hint = did_you_mean(name, known);
  if (!hint.empty()) return hint;
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  return " (expected " + list + ")";
}

int line_of(const YamlNode& n) {
  return n.line() + 1;
}

std::string scalar_text(const std::string& path, const YamlNode& n, const std::string& what) {
  if (!n.is_scalar()) throw InputError(path, line_of(n), fmt::format("{} must be a string", what));
  return n.scalar();
}

// The nodes of a value written as one scalar or as a list: the scalar itself, or the list's items
// (empty for a map or an empty list).
std::vector<const YamlNode*> scalar_or_items(const YamlNode& v) {
  std::vector<const YamlNode*> items;
  if (v.is_scalar())
    items.push_back(&v);
  else if (v.is_sequence())
    for (const auto& x : v.items()) items.push_back(&x);
  return items;
}

// `values` without repeats (first occurrences, in order); a note when some were dropped, and an
// InputError when more than kMaxSceneRoughnessValues remain.
std::vector<double> distinct_roughness(const std::string& path, int line,
                                       const std::vector<double>& values,
                                       std::vector<std::string>& notes) {
  std::vector<double> out;
  for (const double r : values)
    if (std::find(out.begin(), out.end(), r) == out.end()) out.push_back(r);
  if (std::ssize(out) > kMaxSceneRoughnessValues)
    throw InputError(path, line,
                     fmt::format("{} distinct roughness values, more than the {} a scene allows "
                                 "(docs/engines.md): sample the range more coarsely",
                                 out.size(), kMaxSceneRoughnessValues));
  if (out.size() != values.size())
    notes.push_back(fmt::format("{}:{}: {} repeated roughness values merged", path, line,
                                values.size() - out.size()));
  return out;
}

// A roughness or a list of them, each in [0, 1] (0: a mirror).
std::vector<double> roughness_list(const std::string& path, const YamlNode& v, int line) {
  const std::vector<const YamlNode*> items = scalar_or_items(v);
  if (items.empty())
    throw InputError(path, line, "'roughness' must be a number or a list of numbers in [0, 1]");
  std::vector<double> out;
  for (const YamlNode* x : items) {
    double r = 0;
    if (!x->is_scalar() || !parse_finite(x->scalar(), r) || !(r >= 0.0 && r <= 1.0))
      throw InputError(path, line_of(*x),
                       fmt::format("'roughness' must be a perceptual roughness in [0, 1], not '{}'",
                                   x->is_scalar() ? x->scalar() : std::string("a list or map")));
    out.push_back(r);
  }
  return out;
}

// A material: a name, or a map {name, roughness, group}.
SceneFileMaterial scene_material(const std::string& path, const YamlNode& m) {
  if (!m.is_map()) {
    const std::string spec = scalar_text(path, m, "each material");
    if (spec.empty()) throw InputError(path, line_of(m), "empty material name");
    return {spec, line_of(m), {}};
  }
  SceneFileMaterial out{"", line_of(m), {}};
  for (const auto& kv : m.fields()) {
    const std::string key = kv.first.is_scalar() ? kv.first.scalar() : std::string("?");
    if (key == "name")
      out.spec = scalar_text(path, kv.second, "a material's 'name'");
    else if (key == "roughness")
      out.roughness = roughness_list(path, kv.second, line_of(kv.first));
    else if (key == "group") {
      out.group = scalar_text(path, kv.second, "a material's 'group'");
      if (out.group.empty()) throw InputError(path, line_of(kv.second), "empty group name");
    } else
      throw InputError(
          path, line_of(kv.first),
          "unknown material key '" + key + "'" + hint_or_list(key, {"name", "roughness", "group"}));
  }
  if (out.spec.empty())
    throw InputError(path, out.line, "a material given as a map needs a 'name'");
  return out;
}

// The scene's 'lighting': one of punctual, ibl, area or a list of them.
void read_lighting(const std::string& path, const YamlNode& v, int line, SceneFile& s) {
  const std::vector<const YamlNode*> items = scalar_or_items(v);
  if (items.empty())
    throw InputError(path, line, "'lighting' must list any of punctual, ibl, area");
  for (const YamlNode* x : items) {
    const std::string l = scalar_text(path, *x, "each lighting");
    if (l == "punctual")
      s.punctual = true;
    else if (l == "ibl")
      s.ibl = true;
    else if (l == "area")
      s.area = true;
    else
      throw InputError(
          path, line_of(*x),
          "unknown lighting '" + l + "'" + hint_or_list(l, {"punctual", "ibl", "area"}));
  }
}

// The text of a material's entry's line numbers: "2, 3, 4" (the first 5, then "...").
std::string line_list(const std::vector<int>& lines) {
  std::string out;
  for (size_t i = 0; i < lines.size() && i < 5; ++i)
    out += (i ? ", " : "") + std::to_string(lines[i]);
  return lines.size() > 5 ? out + ", ..." : out;
}

// Entries naming the same material merged into the first (roughness joined, groups agreeing),
// each merge noted; then the limits checked.
void merge_materials(SceneFile& s) {
  std::vector<SceneFileMaterial> merged;
  std::vector<std::vector<int>> lines;
  for (auto& m : s.materials) {
    const auto it = std::find_if(merged.begin(), merged.end(),
                                 [&](const SceneFileMaterial& x) { return x.spec == m.spec; });
    if (it == merged.end()) {
      merged.push_back(std::move(m));
      lines.push_back({merged.back().line});
      continue;
    }
    if (it->group != m.group)
      throw InputError(s.path, m.line,
                       fmt::format("'{}' is listed again (first at line {}) with another group",
                                   truncated(m.spec), it->line));
    it->roughness.insert(it->roughness.end(), m.roughness.begin(), m.roughness.end());
    lines[static_cast<size_t>(it - merged.begin())].push_back(m.line);
  }
  for (size_t i = 0; i < merged.size(); ++i) {
    if (lines[i].size() > 1)
      s.notes.push_back(fmt::format("{}: '{}' listed {} times (lines {}): merged into one", s.path,
                                    truncated(merged[i].spec), lines[i].size(),
                                    line_list(lines[i])));
    if (!merged[i].roughness.empty())
      merged[i].roughness =
          distinct_roughness(s.path, merged[i].line, merged[i].roughness, s.notes);
  }
  if (std::ssize(merged) > kMaxSceneMaterials)
    throw InputError(s.path, merged[kMaxSceneMaterials].line,
                     fmt::format("{} distinct materials, more than the {} a scene allows "
                                 "(docs/engines.md): split the scene",
                                 merged.size(), kMaxSceneMaterials));
  s.materials = std::move(merged);
}

}  // namespace

SceneFile read_scene_file(const std::string& path) {
  SceneFile s;
  s.path = path;
  const YamlNode root = read_yaml_file(path);  // missing, directory, empty, binary, invalid YAML
  if (root.is_null()) throw InputError(path, 1, "scene is empty (expected a map with 'materials')");
  if (!root.is_map())
    throw InputError(path, line_of(root), "a scene must be a YAML map with 'materials'");
  bool have_materials = false;
  for (const auto& kv : root.fields()) {
    const std::string key = kv.first.is_scalar() ? kv.first.scalar() : std::string("?");
    const YamlNode& v = kv.second;
    const int line = line_of(kv.first);
    if (key == "materials") {
      have_materials = true;
      if (!v.is_sequence() || v.size() == 0)
        throw InputError(
            path, line,
            "'materials' must be a non-empty list of material names, database pages or files");
      for (const auto& m : v.items()) s.materials.push_back(scene_material(path, m));
    } else if (key == "max_de00") {
      double x = 0;
      if (!v.is_scalar() || !parse_finite(v.scalar(), x) || !(x > 0.0))
        throw InputError(
            path, line,
            fmt::format("'max_de00' must be a positive number (a ΔE2000 budget), not '{}'",
                        v.is_scalar() ? v.scalar() : std::string("a list or map")));
      s.max_de00 = x;
    } else if (key == "space") {
      s.space = scalar_text(path, v, "'space'");
      if (s.space.empty()) throw InputError(path, line, "'space' is empty");
      s.space_line = line;
    } else if (key == "lighting") {
      read_lighting(path, v, line, s);
    } else if (key == "roughness") {
      s.roughness = distinct_roughness(path, line, roughness_list(path, v, line), s.notes);
    } else {
      throw InputError(
          path, line,
          "unknown key '" + key + "'" +
              hint_or_list(key, {"materials", "max_de00", "space", "lighting", "roughness"}));
    }
  }
  if (!have_materials)
    throw InputError(path, 1,
                     "missing 'materials' (a list of material names, database pages or files)");
  merge_materials(s);
  return s;
}

}  // namespace fl::spectral
