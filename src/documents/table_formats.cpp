#include "documents/table_formats.h"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <stdexcept>

#include "documents/json.h"
#include "util/errors.h"
#include "util/suggest.h"

namespace fl::documents {

namespace {
const std::vector<NameChoice>& table_format_choices() {
  static const std::vector<NameChoice> choices{{"csv", {}}, {"md", {"markdown"}}, {"json", {}}};
  return choices;
}
}  // namespace

Format format_from_name(const std::string& name) {
  const auto match = match_name(name, table_format_choices());
  if (!match) throw InputError(unknown_name_message("format", name, table_format_choices()));
  return *match == "csv" ? Format::Csv : *match == "md" ? Format::Markdown : Format::Json;
}

const char* extension(Format f) {
  switch (f) {
    case Format::Csv:
      return "csv";
    case Format::Markdown:
      return "md";
    default:
      return "json";
  }
}

std::string format_number(double v, int precision) {
  std::string s = fmt::format("{:.{}f}", v, precision);
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

namespace {

std::string cell_text(const Cell& c, const Column& col, const char* non_finite) {
  if (const auto* s = std::get_if<std::string>(&c)) return *s;
  if (const auto* i = std::get_if<long long>(&c)) return std::to_string(*i);
  const double v = std::get<double>(c);
  if (!std::isfinite(v)) return non_finite;
  return col.significant ? fmt::format("{:.{}g}", v == 0.0 ? 0.0 : v, col.precision)
                         : format_number(v, col.precision);
}

std::string csv_quote(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"') out += '"';
    out += ch;
  }
  return out + "\"";
}

}  // namespace

std::string to_csv(const Table& t) {
  std::string out;
  bool first = true;
  for (const auto& col : t.columns) {
    if (!col.in_csv) continue;
    out += (first ? "" : ",") + csv_quote(col.name);
    first = false;
  }
  out += '\n';
  out += to_csv_rows(t);
  return out;
}

std::string to_csv_rows(const Table& t) {
  std::string out;
  for (const auto& row : t.rows) {
    bool first = true;
    for (size_t c = 0; c < row.size(); ++c) {
      if (!t.columns[c].in_csv) continue;
      out += (first ? "" : ",") + csv_quote(cell_text(row[c], t.columns[c], ""));
      first = false;
    }
    out += '\n';
  }
  return out;
}

namespace {

// A cell's text in a Markdown table row: '|' escaped, and a line break (a catalog name may hold
// one) a space, since a row is one line.
std::string markdown_cell(const std::string& text) {
  std::string s;
  for (size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (ch == '|')
      s += "\\|";
    else if (ch == '\r' || ch == '\n') {
      if (ch == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      s += ' ';
    } else
      s += ch;
  }
  return s;
}

}  // namespace

std::string to_markdown(const Table& t, int level) {
  std::string out = std::string(level, '#') + " " + t.title + "\n\n";
  if (!t.reading.empty()) out += t.reading + "\n\n";
  out += "|";
  for (const auto& c : t.columns) out += " " + c.name + " |";
  out += "\n|";
  for (const auto& c : t.columns) {
    (void)c;
    out += "---|";
  }
  out += "\n";
  for (const auto& row : t.rows) {
    out += "|";
    for (size_t c = 0; c < row.size(); ++c) {
      out += " " + markdown_cell(cell_text(row[c], t.columns[c], "n/a")) + " |";
    }
    out += "\n";
  }
  if (!t.notes.empty()) {
    out += "\n";
    for (const auto& n : t.notes) out += "- " + n + "\n";
  }
  return out;
}

std::string to_json(const Table& t) {
  std::map<std::string, int> decimals;
  for (const auto& c : t.columns)
    if (!decimals.emplace(c.name, c.precision).second)
      throw std::logic_error(fmt::format("table {}: column '{}' appears twice", t.name, c.name));
  Json rows = Json::array();
  for (const auto& row : t.rows) {
    Json r = Json::object();
    for (size_t c = 0; c < row.size(); ++c)
      std::visit([&](const auto& v) { r[t.columns[c].name] = v; }, row[c]);
    rows.push_back(std::move(r));
  }
  const Json doc = {
      {"name", t.name}, {"title", t.title}, {"rows", std::move(rows)}, {"notes", t.notes}};
  return write_json(doc, [&](const std::string& key) {
    const auto it = decimals.find(key);
    return it == decimals.end() ? 0 : it->second;
  });
}

std::string render(const Table& t, Format f) {
  switch (f) {
    case Format::Csv:
      return to_csv(t);
    case Format::Markdown:
      return to_markdown(t);
    default:
      return to_json(t);
  }
}

}  // namespace fl::documents
