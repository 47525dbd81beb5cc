#pragma once
// Materials: the catalog (one YAML per material under materials/), database pages and files.
#include <memory>
#include <string>
#include <vector>

#include "spectral/pages.h"
#include "spectral/ri_database.h"

namespace fl::spectral {

enum class MaterialClass { Metal, Dielectric };
const char* to_string(MaterialClass c);

struct Material {
  enum class Origin { Catalog, Page, File, Consensus };  // Consensus: analysis/consensus
  Origin origin = Origin::Catalog;
  std::string key;   // catalog file stem ("gold"), a file's stem ("Cu"), or the page
  std::string name;  // display name ("Gold")
  std::vector<std::string> aliases;  // other names that select a catalog entry ("Au", "aluminium")
  MaterialClass material_class = MaterialClass::Metal;
  // Database page, file path (as given when relative, the file's name when absolute: no path of
  // the user's machine in a published output) or "constant n=…".
  std::string source;
  std::string file;       // a file material's path as given (tells two files of one name apart)
  std::string reference;  // citation of the data
  std::string book_name;  // a page's book in the database's catalog ("Au (Gold)"), if listed
  std::string section;    // a page's catalog section ("Experimental data: thin film"), if listed
  bool bulk_measurement =
      false;             // a page measuring the bulk material (pages.h, is_bulk_measurement)
  PageClass page_class;  // a page's kind from the catalog (pages.h, classify_page)
  int order = 0;         // catalog order (the talk's table order)
  double talk_schlick_rms_de00 = -1.0;  // Hoffman 2020's Schlick RMS ΔE2000, when the talk lists it
  OpticalConstants constants;
};

// Where inputs live.
// A file the tool reads and how reports name it (`name`; empty: the path).
struct DataFile {
  std::string path, name;
};

struct CatalogIndex;

struct DataPaths {
  std::string database;   // the folder holding data/
  std::string materials;  // the catalog folder
  DataFile model_costs;   // bench/model_costs.csv (analysis/speed/speed.h)
  DataFile gpu_costs;     // bench/gpu_costs.csv
  // The database's page catalog, owned by the run (the analysis context sets it); without it a
  // page read reads catalog-nk.yml for itself.
  std::shared_ptr<const PageCatalog> pages;
  // The catalog's names, owned by the run likewise (catalog_index).
  std::shared_ptr<const CatalogIndex> catalog;
};
// `paths.pages`, or a catalog of `paths.database` read for this one use.
std::shared_ptr<const PageCatalog> page_catalog(const DataPaths& paths);

// One catalog entry (materials/<key>.yml): its data from a database page (`source:
// main/Au/nk/Johnson`), a file (`file: PATH`, relative to the entry's folder unless absolute; any
// format nk_text.h reads) or a constant index (`constant: {n: 1.64, k: 0}`).
Material read_catalog_entry(const std::string& path, const DataPaths& paths);

// Keys and names select entries case-insensitively (resolve_material): two entries may not share
// either. InputError at the later entry's name, naming the earlier one.
void require_unique_names(const std::vector<std::string>& files, const std::vector<Material>& ms);

// Every catalog entry, in catalog order: the `order` field, then the key.
std::vector<Material> read_catalog(const DataPaths& paths);

// The names that select each catalog entry of a folder: its key (file stem), `name` and `aliases`.
// An entry that cannot be read keeps its error and is selected by its key only; reading it then
// reports the error, and a name that selects nothing lists it (unreadable_entries).
struct CatalogIndex {
  struct Entry {
    std::string file;
    std::vector<std::string> names;
    std::string error;  // empty when the entry's names were read
  };
  std::string folder;
  std::vector<Entry> entries;  // in file-name order
};
CatalogIndex read_catalog_index(const std::string& folder);
// `paths.catalog` when it indexes `paths.materials`, or an index read for this one use.
std::shared_ptr<const CatalogIndex> catalog_index(const DataPaths& paths);
// "; unreadable catalog entries: ERROR; ERROR" for entries whose names could not be read, or "".
std::string unreadable_entries(const DataPaths& paths);
// The file of a database page (main/Au/nk/Johnson): DATABASE/data/PAGE.yml.
std::string database_file(const DataPaths& paths, const std::string& page);

// A catalog key or display name (case-insensitive), a database page (main/Au/nk/Johnson), or a
// file path (a refractiveindex.info page or catalog entry .yml, or any format nk_text.h reads).
// Pages and files get their class from the data (classify).
Material resolve_material(const std::string& spec, const DataPaths& paths);

// A database page (main/Au/nk/Johnson): its file under DATABASE/data/, class from the data.
Material read_database_page(const std::string& page, const DataPaths& paths);

// Metal or dielectric from the data: a metal when the mean k over 400–700 nm (5 nm steps) exceeds
// kMetalMinK. Light entering such a material is absorbed within λ/(4πk) < λ/6 ≈ 0.1 µm: it shows
// only its surface reflection, what shading models call a metal. Caesium (mean k 0.67–0.95 on its
// pages; k at 550 nm just below 1) and tungsten (n > k, so ε′ = n² − k² > 0) are metals; silicon
// (0.08) and glasses are not.
inline constexpr double kMetalMinK = 0.5;
MaterialClass classify(const OpticalConstants& oc);

// A material argument after glob expansion: `spec` is a catalog name, page or file as written, or
// a page matched by the glob `pattern` (empty when the argument named it).
struct MaterialRequest {
  std::string spec;
  std::string pattern;
};
// Expands page globs (pages.h: 'main/*/nk/*', '**') into the matching database pages, sorted, in
// argument order; other arguments stay as given. A glob that matches no page is an InputError.
std::vector<MaterialRequest> expand_materials(const std::vector<std::string>& specs,
                                              const DataPaths& paths);

}  // namespace fl::spectral
