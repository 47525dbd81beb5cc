#pragma once
// Tables as CSV, Markdown and JSON text.
#include <string>

#include "util/table.h"

namespace fl::documents {

enum class Format { Csv, Markdown, Json };
// csv, md (or markdown) or json, ignoring case; InputError otherwise.
Format format_from_name(const std::string& name);
const char* extension(Format f);

// Numbers are printed with the column's fixed precision ("-0.000" is printed as "0.000"), so the
// same results give byte-identical files. Non-finite numbers are written as empty cells (CSV),
// "n/a" (Markdown) or null (JSON).
std::string to_csv(const Table& t);
// The rows alone, without the header line (a table written in parts).
std::string to_csv_rows(const Table& t);
std::string to_markdown(const Table& t, int heading_level = 1);
std::string to_json(const Table& t);
std::string render(const Table& t, Format f);

// `v` with `precision` decimals, "-0.000" printed as "0.000".
std::string format_number(double v, int precision);

}  // namespace fl::documents
