#include "io/writer.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "io/staging.h"
#include "util/errors.h"

namespace fl::io {

namespace {

namespace fs = std::filesystem;

// The folder `path` names, "." for a bare name; "out/" is the folder "out".
fs::path folder_of(const std::string& path) {
  fs::path p = fs::path(path).lexically_normal();
  if (!p.has_filename()) p = p.parent_path();
  return p.has_parent_path() ? p.parent_path() : fs::path(".");
}

// The deepest folder holding every file of `files` (absolute).
fs::path common_folder(const Files& files) {
  fs::path common;
  for (size_t i = 0; i < files.size(); ++i) {
    const fs::path f = fs::absolute(folder_of(files[i].first)).lexically_normal();
    if (i == 0) {
      common = f;
      continue;
    }
    fs::path shared;
    for (auto a = common.begin(), b = f.begin(); a != common.end() && b != f.end() && *a == *b;
         ++a, ++b)
      shared /= *a;
    common = shared;
  }
  return common;
}

// Writes the file at `path` (under `root`) into the staging folder `stage` at the same relative
// path; its error names the user path.
void stage_file(const fs::path& root, const fs::path& stage, const std::string& path,
                const std::string& bytes) {
  std::error_code ec;
  const fs::path rel = fs::absolute(path).lexically_normal().lexically_relative(root);
  if (rel.empty() || *rel.begin() == "..")
    throw std::runtime_error(fmt::format("{}: outside the output folder", path));
  if (fs::is_directory(path, ec))
    throw InputError(path, 0, "is a directory, cannot write a file there");
  fs::create_directories((stage / rel).parent_path(), ec);
  staging::write_checked(stage / rel, bytes, path);
}

void stage_files(const fs::path& root, const fs::path& stage, const Files& files) {
  for (const auto& [path, bytes] : files) stage_file(root, stage, path, bytes);
}

}  // namespace

void require_output_folder(const std::string& path) {
  const fs::path folder = folder_of(path);
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw InputError(path, 0,
                     fmt::format("the folder {} does not exist (outputs never create folders)",
                                 folder.string()));
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw InputError(path, 0, fmt::format("the folder {} is not writable", folder.string()));
}

void write_files_atomic(const Files& files, const std::string& out_folder) {
  if (files.empty()) return;
  std::error_code ec;
  bool created = false;
  if (!out_folder.empty()) {
    require_output_folder(out_folder);
    if (!fs::exists(out_folder, ec)) created = fs::create_directory(out_folder, ec);
  } else {
    for (const auto& f : files) require_output_folder(f.first);
  }
  const fs::path root =
      out_folder.empty() ? common_folder(files) : fs::absolute(out_folder).lexically_normal();
  staging::HoldSignals hold;
  {
    staging::FolderLock lock(root);
    staging::recover(root);
  }
  const std::string suffix = staging::unique_suffix();
  const fs::path stage = root / (staging::kStaging + suffix),
                 committed = root / (staging::kCommitted + suffix);
  try {
    fs::create_directory(stage);
    stage_files(root, stage, files);
  } catch (...) {
    fs::remove_all(stage, ec);
    if (created) fs::remove(out_folder, ec);
    throw;
  }
  staging::FolderLock lock(root);
  fs::rename(stage, committed, ec);  // the commit point
  if (ec) {
    fs::remove_all(stage, ec);
    throw std::runtime_error(
        fmt::format("{}: cannot move the finished files into place", file_list(files)));
  }
  staging::move_in(committed, root);
}

void write_file_atomic(const std::string& path, const std::string& content) {
  write_files_atomic({{path, content}});
}

void require_replaceable_folder(const std::string& folder, const std::string& marker) {
  require_output_folder(folder);
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
  require_replaceable_folder(folder, marker);
  fs::path target = fs::absolute(folder).lexically_normal();
  if (!target.has_filename()) target = target.parent_path();  // "out/" is the folder "out"
  const fs::path parent = target.parent_path();
  const std::string pid = std::to_string(static_cast<long>(::getpid()));
  const fs::path fresh = target.string() + ".new." + pid, ready = target.string() + ".ready." + pid,
                 old = target.string() + ".old." + pid;
  staging::HoldSignals hold;
  {
    staging::FolderLock lock(parent);
    staging::recover(parent);
  }
  std::error_code ec;
  try {
    fs::create_directory(fresh);
    stage_file(target, fresh, (fs::path(folder) / marker).string(), "");
    for (const auto& [path, bytes] : files)
      stage_file(target, fresh, (fs::path(folder) / path).string(), bytes);
  } catch (...) {
    fs::remove_all(fresh, ec);
    throw;
  }
  staging::FolderLock lock(parent);
  fs::rename(fresh, ready, ec);  // the commit point
  if (ec) {
    fs::remove_all(fresh, ec);
    throw std::runtime_error(fmt::format("{}: cannot move the finished folder into place", folder));
  }
  const bool had_old = fs::exists(target, ec);
  if (had_old) fs::rename(target, old);
  fs::rename(ready, target, ec);
  if (ec) {
    if (had_old) fs::rename(old, target);
    fs::remove_all(ready, ec);
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
  std::string ext = fs::path(path).extension().string();
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

}  // namespace fl::io
