#pragma once
// The files of `library`: the preset library of database pages in every preset format, and a
// gallery.
#include <string>
#include <vector>

#include "analysis/library/library.h"
#include "io/writer.h"

namespace fl::jobs {

// Paths relative to the output folder: library.csv / .md / .json (one row per page) and every other
// preset format of documents/preset_formats.h (library.mtlx, library_openpbr.mtlx,
// library_standard_surface.mtlx, library.gltf), models.csv (every model, derived and fitted, per
// page), skipped.csv (every page left out, with its reason),
// spread.csv / .md (the spread between pages of the same metal), index.html (the gallery and those
// tables, searchable and sortable), gallery.md with strips/PAGE.png (the ground truth's colour over
// 0-90° per page, with its flags) when `gallery` is set, and README.md (what went in, what came
// out, what was skipped by reason). `command` is the command line, for README.md.
io::Files library_files(const analysis::Context& ctx, const analysis::Library& lib, bool gallery,
                        const std::string& command);

}  // namespace fl::jobs
