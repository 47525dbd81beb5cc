#pragma once
// The one registry of preset document formats: `presets` writes the one it is asked for,
// `reproduce` and `library` write every entry, so every format is available everywhere.
#include <span>
#include <string>
#include <vector>

#include "analysis/presets/shading_presets.h"
#include "analysis/study/study.h"
#include "documents/materialx.h"
#include "documents/table_formats.h"
#include "io/writer.h"
#include "util/table.h"

namespace fl::documents {

enum class PresetKind { Table, MaterialX, Gltf };

struct PresetFormat {
  const char* name;       // the --format name: csv, md, json, mtlx, gltf
  const char* suffix;     // after the file's stem: "", "_openpbr", "_standard_surface"
  const char* extension;  // csv, md, json, mtlx, gltf
  PresetKind kind;
  Format table_format = Format::Csv;                             // kind Table
  MaterialxShader shader = MaterialxShader::GeneralizedSchlick;  // kind MaterialX
  const char* summary = "";
  const char* alias = nullptr;  // another --format name ("markdown", "materialx")
};

// csv, md, json (the presets table), mtlx with generalized_schlick_bsdf, open_pbr_surface and
// standard_surface, gltf (glTF 2.0 materials), in that order.
std::span<const PresetFormat> preset_formats();

// A --format name: one of the registry's names or aliases, ignoring case; InputError otherwise,
// listing them.
std::string preset_format_name(const std::string& name);

// The entry of `presets --format NAME [--openpbr] [--shader S]`: NAME as preset_format_name reads
// it; --openpbr chooses open_pbr_surface with mtlx (a table's columns otherwise); --shader names
// the MaterialX shading model. InputError for an unknown name, --openpbr with gltf, --shader
// without mtlx.
const PresetFormat& preset_format(const std::string& name, bool openpbr, const std::string& shader);

// What a preset document is made of: the table the table formats print, and the studies whose
// derived parameters the MaterialX and glTF documents hold.
struct PresetSource {
  const analysis::Context& ctx;
  const std::vector<analysis::MaterialStudy>& studies;
  const Table& table;
  analysis::ExportOptions options = {};  // MaterialX and glTF
};
std::string preset_document(const PresetFormat& f, const PresetSource& in);

// Every format of preset_formats() as STEM + suffix + "." + extension, in registry order, except
// the files named in `written` already (a table loop's STEM.csv).
io::Files preset_files(const std::string& stem, const PresetSource& in,
                       const std::vector<std::string>& written = {});

// Every preset file of `stem` (STEM + suffix + "." + extension) with its summary, in registry
// order: the links of a report's navigation and the file lists of its README.
struct PresetFile {
  std::string path;
  const char* summary;
};
std::vector<PresetFile> preset_file_names(const std::string& stem);

}  // namespace fl::documents
