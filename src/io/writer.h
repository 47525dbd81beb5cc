#pragma once
// The one file writer: files written atomically, and the names of output files.
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace fl::report {

// Files to write together: (path, bytes).
using Files = std::vector<std::pair<std::string, std::string>>;

// The one file writer. Several files, all or nothing: every file is written to a temporary name
// beside its path first (creating the parent folder if needed); only when all are complete are they
// renamed into place. On failure the temporaries are removed, so no partial file is ever left.
void write_files_atomic(const Files& path_and_content);
void write_file_atomic(const std::string& path, const std::string& content);  // one file

// A folder of outputs replaced as a whole: `files` (paths relative to `folder`) plus an empty
// `marker` file are written to a new folder beside it, which then takes the place of `folder`, so
// a rerun leaves no stale file of the previous one and a failure leaves the previous one intact.
// An existing `folder` must be empty or hold `marker` (a folder this writer made): anything else
// is an InputError, checked by require_replaceable_folder before the work.
void replace_folder_atomic(const std::string& folder, const Files& files,
                           const std::string& marker);
void require_replaceable_folder(const std::string& folder, const std::string& marker);

// What a command produces: its files, and the lines to show on stderr once they are written.
struct Output {
  Files files;
  std::vector<std::string> messages;
};
// The paths of `files` for a message: "a", "a and b", "a, b and c".
std::string file_list(const Files& files);

// The lower-case extension of `path` (".exr"; empty if none).
std::string lower_extension(const std::string& path);
// lower_extension(path), which must be one of `allowed`; otherwise an InputError naming the path
// and the expected types.
std::string output_extension(const std::string& path, std::initializer_list<const char*> allowed);

}  // namespace fl::report
