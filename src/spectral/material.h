#pragma once
// Materials: the catalog (one YAML per material under materials/), database pages and files.
#include <string>
#include <vector>

#include "spectral/ri_database.h"

namespace fl::spectral {

enum class MaterialClass { Metal, Dielectric };
const char* to_string(MaterialClass c);

struct Material {
  std::string key;        // catalog file stem ("gold"), or the argument it was loaded from
  std::string name;       // display name ("Gold")
  MaterialClass material_class = MaterialClass::Metal;
  std::string source;     // database page, file path or "constant n=…"
  std::string reference;  // citation of the data
  int order = 0;          // catalog order (the talk's table order)
  double talk_schlick_rms_de00 = -1.0;  // Hoffman 2020's Schlick RMS ΔE2000, when the talk lists it
  OpticalConstants constants;
};

// Where inputs live.
struct DataPaths {
  std::string database;   // the folder holding data/
  std::string materials;  // the catalog folder
};

// One catalog entry (materials/<key>.yml). Reads its data from the database.
Material read_catalog_entry(const std::string& path, const DataPaths& paths);

// Every catalog entry, in catalog order: the `order` field, then the key.
std::vector<Material> read_catalog(const DataPaths& paths);

// A catalog key or display name (case-insensitive), a database page (main/Au/nk/Johnson), or a
// file path (.yml refractiveindex.info format or catalog entry, .csv lambda_nm,n,k).
Material resolve_material(const std::string& spec, const DataPaths& paths);

}  // namespace fl::spectral
