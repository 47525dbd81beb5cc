#include "report/writer.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include "spectral/errors.h"

namespace fl::report {

Format format_from_name(const std::string& name) {
  if (name == "csv") return Format::Csv;
  if (name == "md" || name == "markdown") return Format::Markdown;
  if (name == "json") return Format::Json;
  throw InputError(fmt::format("unknown format '{}' (expected csv, md or json)", name));
}

const char* extension(Format f) {
  switch (f) {
    case Format::Csv: return "csv";
    case Format::Markdown: return "md";
    default: return "json";
  }
}

std::string format_number(double v, int precision) {
  std::string s = fmt::format("{:.{}f}", v, precision);
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

namespace {

std::string cell_text(const analysis::Cell& c, int precision, const char* non_finite) {
  if (const auto* s = std::get_if<std::string>(&c)) return *s;
  if (const auto* i = std::get_if<long long>(&c)) return std::to_string(*i);
  const double v = std::get<double>(c);
  return std::isfinite(v) ? format_number(v, precision) : non_finite;
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

std::string json_escape(const std::string& s) {
  std::string out;
  for (unsigned char ch : s) {
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (ch < 0x20) out += fmt::format("\\u{:04x}", ch);
        else out += static_cast<char>(ch);
    }
  }
  return out;
}

std::string to_csv(const analysis::Table& t) {
  std::string out;
  bool first = true;
  for (const auto& col : t.columns) {
    if (!col.in_csv) continue;
    out += (first ? "" : ",") + csv_quote(col.name);
    first = false;
  }
  out += '\n';
  for (const auto& row : t.rows) {
    first = true;
    for (size_t c = 0; c < row.size(); ++c) {
      if (!t.columns[c].in_csv) continue;
      out += (first ? "" : ",") + csv_quote(cell_text(row[c], t.columns[c].precision, ""));
      first = false;
    }
    out += '\n';
  }
  return out;
}

std::string to_markdown(const analysis::Table& t, int level) {
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
      std::string s = cell_text(row[c], t.columns[c].precision, "n/a");
      for (size_t p = s.find('|'); p != std::string::npos; p = s.find('|', p + 2)) s.replace(p, 1, "\\|");
      out += " " + s + " |";
    }
    out += "\n";
  }
  if (!t.notes.empty()) {
    out += "\n";
    for (const auto& n : t.notes) out += "- " + n + "\n";
  }
  return out;
}

std::string to_json(const analysis::Table& t) {
  std::string out = "{\n  \"name\": \"" + json_escape(t.name) + "\",\n  \"title\": \"" + json_escape(t.title) +
                    "\",\n  \"rows\": [";
  for (size_t r = 0; r < t.rows.size(); ++r) {
    out += r ? ",\n    {" : "\n    {";
    for (size_t c = 0; c < t.rows[r].size(); ++c) {
      out += (c ? ", \"" : "\"") + json_escape(t.columns[c].name) + "\": ";
      const auto& cell = t.rows[r][c];
      if (const auto* s = std::get_if<std::string>(&cell)) out += "\"" + json_escape(*s) + "\"";
      else out += cell_text(cell, t.columns[c].precision, "null");
    }
    out += "}";
  }
  out += t.rows.empty() ? "],\n" : "\n  ],\n";
  out += "  \"notes\": [";
  for (size_t i = 0; i < t.notes.size(); ++i) out += (i ? ", \"" : "\"") + json_escape(t.notes[i]) + "\"";
  out += "]\n}\n";
  return out;
}

std::string render(const analysis::Table& t, Format f) {
  switch (f) {
    case Format::Csv: return to_csv(t);
    case Format::Markdown: return to_markdown(t);
    default: return to_json(t);
  }
}

namespace {

// Writes `content` to a temporary file beside `path`; returns its name.
std::string write_temporary(const std::string& path, const std::string& content) {
  namespace fs = std::filesystem;
  const fs::path p(path);
  std::error_code ec;
  if (p.has_parent_path()) fs::create_directories(p.parent_path(), ec);
  if (fs::is_directory(p, ec)) throw InputError(path, 0, "is a directory, cannot write a file there");
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

void write_files_atomic(const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<std::string> temps;
  try {
    for (const auto& [path, content] : files) temps.push_back(write_temporary(path, content));
  } catch (...) {
    for (const auto& t : temps) std::remove(t.c_str());
    throw;
  }
  for (size_t i = 0; i < files.size(); ++i) {
    std::error_code ec;
    std::filesystem::rename(temps[i], files[i].first, ec);
    if (ec) {
      for (size_t j = i; j < temps.size(); ++j) std::remove(temps[j].c_str());
      throw std::runtime_error(fmt::format("{}: cannot move the finished file into place: {}", files[i].first, ec.message()));
    }
  }
}

void write_file_atomic(const std::string& path, const std::string& content) { write_files_atomic({{path, content}}); }

}  // namespace fl::report
