#pragma once
// A table of results, independent of how it is written (CSV, Markdown and JSON are in
// documents/table_formats.h).
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace fl {

struct Column {
  std::string name;
  int precision = 4;  // decimals for numeric cells (significant digits if `significant`)
  bool in_csv =
      true;  // false: Markdown/JSON only (the CSV keeps the stable columns of docs/conventions.md)
  bool significant = false;  // CSV and Markdown print `precision` significant digits (%g)
};

using Cell = std::variant<std::string, double, long long>;

struct Table {
  std::string name;   // file stem: schlick, methods, ...
  std::string title;  // Markdown heading
  std::vector<Column> columns;
  std::vector<std::vector<Cell>> rows;
  std::string reading;             // a short reading of what the table shows (Markdown)
  std::vector<std::string> notes;  // conventions, flags (Markdown bullet list)
};

// The index of the column named `name`; a table without it is a programming error.
inline int column_index(const Table& t, const std::string& name) {
  for (size_t i = 0; i < t.columns.size(); ++i)
    if (t.columns[i].name == name) return static_cast<int>(i);
  throw std::logic_error("table " + t.name + " has no column " + name);
}

}  // namespace fl
