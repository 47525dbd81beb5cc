#pragma once
// Where Fresnel Lab finds what it reads when no option names it: the only place that reads
// environment variables and the executable's location (docs/install.md).
#include <string>

#include "spectral/material.h"

namespace fl::cli {

struct Locations {
  // The tool's own data (materials/, bench/model_costs.csv, bench/gpu_costs.csv): PREFIX/share/
  // fresnel-lab for an installed tool, the source tree for a build tree's executable; empty when
  // neither is found.
  std::string data;
  bool installed = false;  // found through bin/../share/fresnel-lab
  std::string source;      // the build tree's source tree (empty when installed)
};

// The running executable's path (/proc/self/exe).
std::string executable_path();

// From the executable's folder `bin`: `bin/../share/fresnel-lab` when it holds materials/, else
// the source tree named by `bin/fresnel-lab-source.txt` (written by CMake beside the build's
// executable, never installed).
Locations find_locations(const std::string& bin);

// The defaults the command line starts from: the database ($FRESNEL_LAB_DB, else for a build
// tree SOURCE/../shared/refractiveindex.info-database/database, else empty: an installed tool
// needs --db or $FRESNEL_LAB_DB), the catalog (DATA/materials), the costs ($FRESNEL_LAB_COSTS,
// $FRESNEL_LAB_GPU_COSTS, else DATA/bench/model_costs.csv and DATA/bench/gpu_costs.csv, named
// bench/… in reports).
spectral::DataPaths default_paths(const Locations& where);

// $OCIO, or empty.
std::string default_ocio_config();
// $FRESNEL_LAB_FONT, or empty (draw/drawing.h: DejaVu Sans through fontconfig).
std::string label_font_file();

// The message for a database folder that is not one (no data/ under it).
std::string database_missing_message(const Locations& where);

}  // namespace fl::cli
