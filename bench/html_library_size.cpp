// The HTML report at database scale: every database page under a folder that loads (for example
// data/main, every element) becomes a gallery card (material_card, no renders), with the presets
// and every model's errors (derived parameters; fitted rows have the same size) as tables; prints
// the page's size and how it splits. A measurement of the serializer, not a preset library.
//   html_library_size [--pages data/main] [--out FILE.html]
#include <fmt/format.h>

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/presets/preset_tables.h"
#include "analysis/tables/tables.h"
#include "documents/html.h"
#include "documents/table_formats.h"
#include "io/writer.h"
#include "jobs/pictures.h"

using namespace fl;

int main(int argc, char** argv) {
  std::string pages = "data/main", out;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::string(argv[i]) == "--pages") pages = argv[i + 1];
    if (std::string(argv[i]) == "--out") out = argv[i + 1];
  }
  analysis::Settings settings;
  settings.paths = {FRESNEL_LAB_DEFAULT_DB, FRESNEL_LAB_DEFAULT_MATERIALS};
  const analysis::Context ctx(settings);
  std::vector<std::string> specs;
  const std::filesystem::path root = std::filesystem::path(settings.paths.database) / pages;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root))
    if (e.is_regular_file() && e.path().extension() == ".yml")
      specs.push_back(std::filesystem::relative(
                          e.path(), std::filesystem::path(settings.paths.database) / "data")
                          .replace_extension("")
                          .string());
  std::sort(specs.begin(), specs.end());
  std::vector<analysis::LoadedMaterial> materials;
  for (const auto& s : specs) {
    try {
      materials.push_back(
          analysis::load_material(ctx, spectral::resolve_material(s, settings.paths)));
    } catch (const std::exception&) {
      // refused pages are not in the gallery
    }
  }
  analysis::StudyOptions options;
  options.fit = false;
  const auto studies = analysis::study_materials(ctx, materials, options);
  documents::HtmlReport page;
  page.title = "Database gallery";
  const std::vector<Table> tables{analysis::presets_table(ctx, studies),
                                  analysis::models_table(ctx, studies)};
  page.tables = tables;
  page.gallery = jobs::catalog_gallery(ctx, studies, page.tables[0], false, {});
  const auto html = documents::html_report(page);
  const auto gallery = documents::gallery_html(page.gallery);
  const auto presets = documents::table_html(page.tables[0], "p"),
             models = documents::table_html(page.tables[1], "m");
  fmt::print(
      "{} pages under {}, {} loaded: index.html {} bytes (gallery {}, presets table {}, models "
      "table {} with {} "
      "rows)\n",
      specs.size(), pages, materials.size(), html.size(), gallery.size(), presets.size(),
      models.size(), page.tables[1].rows.size());
  if (!out.empty()) io::write_file_atomic(out, html);
  return 0;
}
