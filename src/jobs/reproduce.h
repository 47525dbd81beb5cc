#pragma once
// `reproduce`: every report file, computed before anything is written.
#include <functional>
#include <string>
#include <vector>

#include "analysis/tables/table_registry.h"
#include "draw/drawing.h"
#include "io/writer.h"

namespace fl::jobs {

// Every table of table_specs() marked for reproduce as NAME.csv and NAME.md, the presets in every
// other format of documents/preset_formats.h (presets.json, presets*.mtlx, presets.gltf), the
// figures (reproduce_figures) labelled in `figures_font` unless it is null (no figures), and
// README.md indexing them; paths relative to the output folder. `log` gets one progress line per
// table and one for the figures. index.html opens with report_summary's findings and shows the
// look-dev sheets `lookdev` (paths relative to the output folder; files reproduce does not write).
io::Files reproduce_files(analysis::TableInputs& in, const draw::LabelFont* figures_font,
                          const std::function<void(const std::string&)>& log,
                          const std::vector<std::string>& lookdev = {});

}  // namespace fl::jobs
