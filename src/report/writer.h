#pragma once
// Writing tables as CSV, Markdown and JSON, and files atomically.
#include <string>
#include <utility>
#include <vector>

#include "analysis/table.h"

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

// Writes to a temporary file beside `path`, then renames it into place: a failure never leaves
// a partial file. Creates the parent folder if needed.
void write_file_atomic(const std::string& path, const std::string& content);

// Several files, all or nothing: every file is written to a temporary name first; only when all
// are complete are they renamed into place. On failure the temporaries are removed.
void write_files_atomic(const std::vector<std::pair<std::string, std::string>>& path_and_content);

std::string json_escape(const std::string& s);
std::string format_number(double v, int precision);

}  // namespace fl::report
