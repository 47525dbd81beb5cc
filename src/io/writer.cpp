#include "io/writer.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "util/errors.h"

namespace fl::report {

namespace {

// Writes `content` to a temporary file beside `path`; returns its name.
std::string write_temporary(const std::string& path, const std::string& content) {
  namespace fs = std::filesystem;
  const fs::path p(path);
  std::error_code ec;
  if (p.has_parent_path()) fs::create_directories(p.parent_path(), ec);
  if (fs::is_directory(p, ec))
    throw InputError(path, 0, "is a directory, cannot write a file there");
  const std::string tmp = fmt::format("{}.tmp.{}", path, static_cast<long>(::getpid()));
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path, 0, "cannot write (folder missing or not writable)");
  out << content;
  out.close();
  if (!out) {
    std::remove(tmp.c_str());
    throw std::runtime_error(fmt::format("{}: write failed", path));
  }
  return tmp;
}

}  // namespace

void write_files_atomic(const Files& files) {
  // The temporaries are written in file order; on a failure every one written is removed.
  std::vector<std::string> temps(files.size());
  try {
    for (size_t i = 0; i < files.size(); ++i)
      temps[i] = write_temporary(files[i].first, files[i].second);
  } catch (...) {
    for (const auto& t : temps)
      if (!t.empty()) std::remove(t.c_str());
    throw;
  }
  for (size_t i = 0; i < files.size(); ++i) {
    std::error_code ec;
    std::filesystem::rename(temps[i], files[i].first, ec);
    if (ec) {
      for (size_t j = i; j < temps.size(); ++j) std::remove(temps[j].c_str());
      throw std::runtime_error(fmt::format("{}: cannot move the finished file into place: {}",
                                           files[i].first, ec.message()));
    }
  }
}

void write_file_atomic(const std::string& path, const std::string& content) {
  write_files_atomic({{path, content}});
}

void require_replaceable_folder(const std::string& folder, const std::string& marker) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(folder, ec)) return;
  if (!fs::is_directory(folder, ec)) throw InputError(folder, 0, "exists and is not a folder");
  if (fs::exists(fs::path(folder) / marker, ec) || fs::is_empty(folder, ec)) return;
  throw InputError(folder, 0,
                   fmt::format("not empty and not a folder Fresnel Lab wrote (no {}): choose a new "
                               "or empty folder, nothing of it is replaced",
                               marker));
}

void replace_folder_atomic(const std::string& folder, const Files& files,
                           const std::string& marker) {
  namespace fs = std::filesystem;
  require_replaceable_folder(folder, marker);
  fs::path target = fs::path(folder).lexically_normal();
  if (!target.has_filename()) target = target.parent_path();  // "out/" is the folder "out"
  const std::string suffix = fmt::format(".{}", static_cast<long>(::getpid()));
  const fs::path fresh = target.string() + ".new" + suffix, old = target.string() + ".old" + suffix;
  std::error_code ec;
  fs::remove_all(fresh, ec);
  try {
    Files inside{{(fresh / marker).string(), ""}};
    for (const auto& [path, bytes] : files) inside.emplace_back((fresh / path).string(), bytes);
    write_files_atomic(inside);
  } catch (...) {
    fs::remove_all(fresh, ec);
    throw;
  }
  const bool had_old = fs::exists(target, ec);
  if (had_old) fs::rename(target, old);
  fs::rename(fresh, target, ec);
  if (ec) {
    if (had_old) fs::rename(old, target);
    throw std::runtime_error(
        fmt::format("{}: cannot move the finished folder into place: {}", folder, ec.message()));
  }
  if (had_old) fs::remove_all(old, ec);
}

std::string file_list(const Files& files) {
  std::string out;
  for (size_t i = 0; i < files.size(); ++i)
    out += (i == 0 ? "" : i + 1 == files.size() ? " and " : ", ") + files[i].first;
  return out;
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext;
}

std::string output_extension(const std::string& path, std::initializer_list<const char*> allowed) {
  const std::string ext = lower_extension(path);
  std::string list;
  for (const char* a : allowed) {
    if (ext == a) return ext;
    list += (list.empty() ? "" : ", ") + std::string(a);
  }
  throw InputError(
      path, 0,
      fmt::format("unknown output type '{}' (expected {})", ext.empty() ? "(none)" : ext, list));
}

}  // namespace fl::report
