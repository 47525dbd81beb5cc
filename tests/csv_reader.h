#pragma once
// The tests' one CSV reader: the tool's own CSV (comma-separated, RFC 4180 quotes, `# ` comment
// lines before the header in some files), the test data's CSV files and the manifests' TSV.
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fl::test {

using CsvRow = std::vector<std::string>;
using CsvRecord = std::map<std::string, std::string>;

// One line's cells: split on `sep` outside double quotes; a quoted cell loses its quotes and a
// doubled quote inside it reads as one. A trailing separator gives a last, empty cell.
inline CsvRow csv_cells(const std::string& line, char sep = ',') {
  CsvRow cells;
  std::string cell;
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"')
      cell += '"', ++i;
    else if (c == '"')
      quoted = !quoted;
    else if (c == sep && !quoted)
      cells.push_back(cell), cell.clear();
    else
      cell += c;
  }
  cells.push_back(cell);
  return cells;
}

struct CsvOptions {
  char separator = ',';
  bool skip_comments = false;  // lines starting with '#'
};

// Every non-empty line of `text` as cells (a line's trailing '\r' dropped).
inline std::vector<CsvRow> csv_rows(const std::string& text, CsvOptions options = {}) {
  std::vector<CsvRow> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || (options.skip_comments && line[0] == '#')) continue;
    rows.push_back(csv_cells(line, options.separator));
  }
  return rows;
}

inline std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

inline std::vector<CsvRow> csv_file_rows(const std::string& path, CsvOptions options = {}) {
  return csv_rows(read_text_file(path), options);
}

// The rows after the header (the first row) as maps from column name to cell.
inline std::vector<CsvRecord> csv_records(const std::string& text, CsvOptions options = {}) {
  const auto rows = csv_rows(text, options);
  std::vector<CsvRecord> out;
  for (size_t i = 1; i < rows.size(); ++i) {
    CsvRecord r;
    for (size_t c = 0; c < rows[0].size() && c < rows[i].size(); ++c) r[rows[0][c]] = rows[i][c];
    out.push_back(r);
  }
  return out;
}

// A row's cells as numbers (std::stod: throws on a cell that is not one).
inline std::vector<double> csv_numbers(const CsvRow& row) {
  std::vector<double> v;
  for (const auto& cell : row) v.push_back(std::stod(cell));
  return v;
}

}  // namespace fl::test
