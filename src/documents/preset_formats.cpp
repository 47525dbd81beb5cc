#include "documents/preset_formats.h"

#include <algorithm>
#include <array>

#include "documents/gltf.h"
#include "util/errors.h"
#include "util/suggest.h"

namespace fl::documents {
namespace {

constexpr std::array kFormats{
    PresetFormat{"csv", "", "csv", PresetKind::Table, Format::Csv, {}, "CSV table"},
    PresetFormat{
        "md", "", "md", PresetKind::Table, Format::Markdown, {}, "Markdown table", "markdown"},
    PresetFormat{"json", "", "json", PresetKind::Table, Format::Json, {}, "JSON table"},
    PresetFormat{"mtlx",
                 "",
                 "mtlx",
                 PresetKind::MaterialX,
                 {},
                 MaterialxShader::GeneralizedSchlick,
                 "MaterialX, generalized_schlick_bsdf",
                 "materialx"},
    PresetFormat{"mtlx",
                 "_openpbr",
                 "mtlx",
                 PresetKind::MaterialX,
                 {},
                 MaterialxShader::OpenPbrSurface,
                 "MaterialX, open_pbr_surface"},
    PresetFormat{"mtlx",
                 "_standard_surface",
                 "mtlx",
                 PresetKind::MaterialX,
                 {},
                 MaterialxShader::StandardSurface,
                 "MaterialX, standard_surface"},
    PresetFormat{"gltf", "", "gltf", PresetKind::Gltf, {}, {}, "glTF 2.0 materials"}};

std::vector<NameChoice> format_choices() {
  std::vector<NameChoice> choices;
  for (const auto& f : kFormats) {
    if (!choices.empty() && choices.back().name == f.name) continue;
    choices.push_back({f.name, {}});
    if (f.alias) choices.back().aliases.push_back(f.alias);
  }
  return choices;
}

}  // namespace

std::span<const PresetFormat> preset_formats() {
  return kFormats;
}

std::string preset_format_name(const std::string& name) {
  const auto choices = format_choices();
  const auto match = match_name(name, choices);
  if (!match) throw InputError(unknown_name_message("format", name, choices));
  return *match;
}

std::vector<PresetFile> preset_file_names(const std::string& stem) {
  std::vector<PresetFile> out;
  for (const auto& f : kFormats) out.push_back({stem + f.suffix + "." + f.extension, f.summary});
  return out;
}

const PresetFormat& preset_format(const std::string& name, bool openpbr,
                                  const std::string& shader) {
  const std::string format = preset_format_name(name);
  if (openpbr && format == "gltf")
    throw InputError(
        "presets: --openpbr does not apply to --format gltf (glTF materials are "
        "metallic-roughness; use mtlx, csv, md or json)");
  if (!shader.empty() && format != "mtlx")
    throw InputError("presets: --shader applies to --format mtlx only, not " + format);
  const auto wanted = !shader.empty() ? materialx_shader_from_name(shader)
                      : openpbr       ? MaterialxShader::OpenPbrSurface
                                      : MaterialxShader::GeneralizedSchlick;
  for (const auto& f : kFormats)
    if (f.name == format && (f.kind != PresetKind::MaterialX || f.shader == wanted)) return f;
  throw InputError("no preset format " + format);  // unreachable: preset_format_name checked it
}

std::string preset_document(const PresetFormat& f, const PresetSource& in) {
  switch (f.kind) {
    case PresetKind::Table:
      return render(in.table, f.table_format);
    case PresetKind::MaterialX:
      return presets_materialx(in.ctx, in.studies, f.shader, in.options);
    case PresetKind::Gltf:
      return presets_gltf(in.ctx, in.studies, in.options);
  }
  return {};
}

io::Files preset_files(const std::string& stem, const PresetSource& in,
                       const std::vector<std::string>& written) {
  io::Files files;
  for (const auto& f : kFormats) {
    const std::string path = stem + f.suffix + "." + f.extension;
    if (std::find(written.begin(), written.end(), path) == written.end())
      files.emplace_back(path, preset_document(f, in));
  }
  return files;
}

}  // namespace fl::documents
