#pragma once
// Writing tables as CSV, Markdown and JSON, and files atomically.
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "analysis/tables/table.h"

namespace fl::report {

enum class Format { Csv, Markdown, Json };
Format format_from_name(const std::string& name);  // csv | md | json
const char* extension(Format f);

// Numbers are printed with the column's fixed precision ("-0.000" is printed as "0.000"), so the
// same results give byte-identical files. Non-finite numbers are written as empty cells (CSV),
// "n/a" (Markdown) or null (JSON).
std::string to_csv(const analysis::Table& t);
std::string to_markdown(const analysis::Table& t, int heading_level = 1);
std::string to_json(const analysis::Table& t);
std::string render(const analysis::Table& t, Format f);

// Files to write together: (path, bytes).
using Files = std::vector<std::pair<std::string, std::string>>;

// The one file writer. Several files, all or nothing: every file is written to a temporary name
// beside its path first (creating the parent folder if needed); only when all are complete are they
// renamed into place. On failure the temporaries are removed, so no partial file is ever left.
void write_files_atomic(const Files& path_and_content);
void write_file_atomic(const std::string& path, const std::string& content);  // one file

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

std::string format_number(double v, int precision);

}  // namespace fl::report
