#include "cli/locations.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fl::cli {
namespace fs = std::filesystem;

namespace {

std::string environment(const char* name) {
  const char* v = std::getenv(name);
  return v && *v ? std::string(v) : std::string();
}

std::string first_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
  return line;
}

spectral::DataFile data_file(const char* env, const Locations& where, const std::string& rel) {
  if (auto path = environment(env); !path.empty()) return {path, path};
  if (where.data.empty()) return {};
  return {(fs::path(where.data) / rel).string(), rel};
}

}  // namespace

std::string executable_path() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : exe.string();
}

Locations find_locations(const std::string& bin) {
  Locations where;
  if (bin.empty()) return where;
  std::error_code ec;
  const fs::path share = (fs::path(bin) / ".." / "share" / "fresnel-lab").lexically_normal();
  if (fs::is_directory(share / "materials", ec)) {
    where.data = share.string();
    where.installed = true;
    return where;
  }
  const std::string source = first_line(fs::path(bin) / "fresnel-lab-source.txt");
  if (!source.empty() && fs::is_directory(fs::path(source) / "materials", ec)) {
    where.data = source;
    where.source = source;
  }
  return where;
}

spectral::DataPaths default_paths(const Locations& where) {
  spectral::DataPaths p;
  p.database = environment("FRESNEL_LAB_DB");
  if (p.database.empty() && !where.source.empty())
    p.database = (fs::path(where.source).parent_path() / "shared" /
                  "refractiveindex.info-database" / "database")
                     .string();
  if (!where.data.empty()) p.materials = (fs::path(where.data) / "materials").string();
  p.model_costs = data_file("FRESNEL_LAB_COSTS", where, "bench/model_costs.csv");
  p.gpu_costs = data_file("FRESNEL_LAB_GPU_COSTS", where, "bench/gpu_costs.csv");
  return p;
}

std::string default_ocio_config() {
  return environment("OCIO");
}

std::string label_font_file() {
  return environment("FRESNEL_LAB_FONT");
}

std::string database_missing_message(const Locations& where) {
  if (where.installed)
    return "not a refractiveindex.info database (no data/ folder); an installed fresnel-lab needs "
           "--db DIR or $FRESNEL_LAB_DB";
  return "not a refractiveindex.info database (no data/ folder); set --db or FRESNEL_LAB_DB";
}

}  // namespace fl::cli
