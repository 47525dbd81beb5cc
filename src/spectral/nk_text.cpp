#include "spectral/nk_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "spectral/ri_database.h"
#include "spectral/tabulated.h"
#include "spectral/text_file.h"
#include "util/errors.h"

namespace fl::spectral {
namespace {

constexpr double kNmPerUm = 1000.0;

// ---- Table headers ----

enum class Role { Wavelength, N, K };
enum class Separator { Comma, Tab, Whitespace };

struct HeaderColumn {
  Role role;
  std::string name;        // as written (trimmed)
  double nm_per_unit = 0;  // wavelength column: 1 (nm), 1000 (µm); 0 when the name gives no unit
};

struct Header {
  Separator separator = Separator::Comma;
  std::vector<HeaderColumn> columns;
  int wavelength = -1, n = -1, k = -1;  // column indices
  int line = 0;
};

// Lower-case ASCII words of a column name; µ (U+00B5), μ (U+03BC) become u and λ (U+03BB) lambda.
std::vector<std::string> name_words(std::string_view name) {
  std::string s;
  for (size_t i = 0; i < name.size(); ++i) {
    const auto c = static_cast<unsigned char>(name[i]);
    const auto next = i + 1 < name.size() ? static_cast<unsigned char>(name[i + 1]) : 0;
    if ((c == 0xC2 && next == 0xB5) || (c == 0xCE && next == 0xBC))
      s += 'u', ++i;
    else if (c == 0xCE && next == 0xBB)
      s += " lambda ", ++i;
    else
      s += std::isalnum(c) ? static_cast<char>(std::tolower(c)) : ' ';
  }
  std::vector<std::string> words;
  for (auto w : split_fields(s, " ")) words.emplace_back(w);
  return words;
}

// nm per unit for a unit word, 0 for anything else.
double unit_word(const std::string& w) {
  if (w == "nm" || w == "nanometer" || w == "nanometers" || w == "nanometre" || w == "nanometres")
    return 1.0;
  if (w == "um" || w == "micron" || w == "microns" || w == "micrometer" || w == "micrometers" ||
      w == "micrometre" || w == "micrometres")
    return kNmPerUm;
  return 0.0;
}

std::optional<HeaderColumn> header_column(std::string_view field) {
  const auto words = name_words(field);
  if (words.empty()) return std::nullopt;
  const std::string& w = words.front();
  HeaderColumn c{Role::Wavelength, std::string(trim(field)), 0.0};
  if (w == "wl" || w == "lambda" || w == "wavelength" || w == "wavelengths" || w == "wave") {
    for (size_t i = 1; i < words.size(); ++i)
      if (const double u = unit_word(words[i]); u > 0) c.nm_per_unit = u;
    if (w == "wl" && c.nm_per_unit == 0)
      c.nm_per_unit = kNmPerUm;  // refractiveindex.info's convention
    return c;
  }
  for (const auto& [role, names] : {std::pair{Role::N, std::vector<std::string>{"n", "eta"}},
                                    std::pair{Role::K, std::vector<std::string>{"k", "kappa"}}})
    if (words.size() == 1 && std::find(names.begin(), names.end(), w) != names.end()) {
      c.role = role;
      return c;
    }
  return std::nullopt;
}

// Fields of a line: comma-separated with "quoted" fields, tab-separated, or whitespace runs.
// Comma and tab splitting keep empty fields, so that a missing value is reported.
std::vector<std::string> split_line(std::string_view line, Separator sep) {
  std::vector<std::string> out;
  if (sep == Separator::Whitespace) {
    for (auto f : split_fields(line, " \t")) out.emplace_back(f);
    return out;
  }
  const char delim = sep == Separator::Comma ? ',' : '\t';
  std::string cur;
  bool quoted = false;
  for (const char c : line) {
    if (c == '"' && sep == Separator::Comma)
      quoted = !quoted;
    else if (c == delim && !quoted)
      out.emplace_back(trim(cur)), cur.clear();
    else
      cur += c;
  }
  out.emplace_back(trim(cur));
  return out;
}

Separator separator_of(std::string_view line) {
  if (line.find(',') != std::string_view::npos) return Separator::Comma;
  if (line.find('\t') != std::string_view::npos) return Separator::Tab;
  return Separator::Whitespace;
}

// A field that is only a unit ("(nm)", "µm") belongs to the column before it: "wavelength (nm)"
// split on whitespace, or "Wavelength, µm" split on its comma.
bool unit_only(std::string_view field) {
  const auto words = name_words(field);
  return words.size() == 1 && unit_word(words.front()) > 0;
}

Header parse_header(const std::string& file, int line, std::string_view text) {
  Header h;
  h.line = line;
  h.separator = separator_of(text);
  std::vector<std::string> fields;
  for (auto& f : split_line(text, h.separator)) {
    if (unit_only(f) && !fields.empty())
      fields.back() += " " + f;
    else
      fields.push_back(std::move(f));
  }
  for (const auto& f : fields) {
    const auto c = header_column(f);
    if (!c)
      throw InputError(
          file, line,
          fmt::format("column '{}' is not a wavelength, n or k (header names: wl, lambda or "
                      "wavelength with its unit, n, k)",
                      f));
    int& slot = c->role == Role::Wavelength ? h.wavelength : c->role == Role::N ? h.n : h.k;
    if (slot >= 0)
      throw InputError(file, line, fmt::format("two columns give the same quantity ('{}')", f));
    slot = static_cast<int>(h.columns.size());
    h.columns.push_back(*c);
  }
  if (h.wavelength < 0)
    throw InputError(file, line,
                     "the header names no wavelength column (wl, lambda or wavelength)");
  if (h.n < 0 && h.k < 0)
    throw InputError(file, line, "the header names neither an n nor a k column");
  return h;
}

DispersionBlock::Kind kind_of(const Header& h) {
  if (h.n >= 0 && h.k >= 0) return DispersionBlock::Kind::TabulatedNK;
  return h.n >= 0 ? DispersionBlock::Kind::TabulatedN : DispersionBlock::Kind::TabulatedK;
}

// ---- Tables ----

struct Section {
  Header header;
  TabulatedRows rows;
};

bool starts_with_number(std::string_view line) {
  const auto fields = split_line(line, separator_of(line));
  double v;
  return !fields.empty() && parse_finite(fields.front(), v);
}

double nm_per_unit(const Header& h) {
  const double u = h.columns[h.wavelength].nm_per_unit;
  return u > 0 ? u : 1.0;
}

void add_table_row(Section& s, const std::string& file, int line, std::string_view text) {
  const Header& h = s.header;
  const auto f = split_line(text, h.separator);
  const auto field = [&](int c) { return c < static_cast<int>(f.size()) ? f[c] : std::string(); };
  double v[3] = {0, 0, 0};  // wavelength, n, k
  if (!parse_finite(field(h.wavelength), v[0]))
    throw InputError(file, line,
                     fmt::format("column '{}': '{}' is not a finite number",
                                 h.columns[h.wavelength].name, field(h.wavelength)));
  const double lambda_nm = v[0] * nm_per_unit(h);
  if (f.size() != h.columns.size())
    return s.rows.add_defect(
        line, lambda_nm, fmt::format("expected {} columns, found {}", h.columns.size(), f.size()));
  for (const auto& [c, out] : {std::pair{h.n, &v[1]}, std::pair{h.k, &v[2]}})
    if (c >= 0 && !parse_finite(field(c), *out))
      return s.rows.add_defect(
          line, lambda_nm,
          fmt::format("column '{}': '{}' is not a finite number", h.columns[c].name, field(c)));
  s.rows.add(line, lambda_nm, v[1], v[2]);
}

// Wavelengths that miss the used range in the header's unit but would overlap it in the other.
void check_units(const std::string& file, const Header& h, const DispersionBlock& b,
                 const UsedRange& used) {
  if (b.max_nm >= used.min_nm && b.min_nm <= used.max_nm) return;
  const auto& col = h.columns[h.wavelength];
  const double unit = nm_per_unit(h), other = unit == 1.0 ? kNmPerUm : 1.0;
  if (b.max_nm / unit * other < used.min_nm || b.min_nm / unit * other > used.max_nm) return;
  const std::string why = col.nm_per_unit > 0 ? fmt::format("the header '{}' says {}", col.name,
                                                            unit == 1.0 ? "nm" : "um")
                                              : fmt::format("'{}' names no unit, so nm", col.name);
  throw InputError(
      file, h.line,
      fmt::format("wavelengths {:g}-{:g} read in {} ({}) miss {:g}-{:g} nm, but in {} they "
                  "would overlap it: write the unit in the header (e.g. 'wavelength_{}')",
                  b.min_nm / unit, b.max_nm / unit, unit == 1.0 ? "nm" : "um", why, used.min_nm,
                  used.max_nm, other == 1.0 ? "nm" : "um", other == 1.0 ? "nm" : "um"));
}

}  // namespace

OpticalConstants read_nk_table(const std::string& path, const UsedRange& used) {
  const std::string text = read_text_file(path);
  const auto lines = split_lines(text);
  std::vector<Section> sections;
  for (size_t i = 0; i < lines.size(); ++i) {
    const int line = static_cast<int>(i + 1);
    const auto t = trim(lines[i]);
    if (t.empty() || t[0] == '#') continue;
    if (!starts_with_number(t)) {
      const Header h = parse_header(path, line, t);
      sections.push_back({h, TabulatedRows(path, kind_of(h), line)});
    } else if (sections.empty()) {
      throw InputError(
          path, line,
          "expected a header line naming the columns (e.g. 'wavelength_nm,n,k'), found numbers");
    } else {
      add_table_row(sections.back(), path, line,
                    lines[i]);  // untrimmed: a trailing tab ends an empty field
    }
  }
  if (sections.empty()) throw InputError(path, 0, "no header line");
  OpticalConstants oc;
  oc.file = path;
  for (const auto& s : sections) {
    if (s.rows.empty()) throw InputError(path, s.header.line, "no data rows under this header");
    oc.blocks.push_back(s.rows.finish(used, oc.warnings));
    check_units(path, s.header, oc.blocks.back(), used);
  }
  if (std::none_of(oc.blocks.begin(), oc.blocks.end(),
                   [](const DispersionBlock& b) { return b.defines_n(); }))
    throw InputError(path, 0, "no column gives n (only k)");
  return oc;
}

namespace {

// ---- Value streams (SOPRA, .spd) ----

struct Token {
  int line;
  std::string text;
};

// Every field after the first `skip_lines` non-empty, non-comment lines, with its line.
std::vector<Token> tokens(std::string_view text, size_t skip_lines, const char* delimiters) {
  std::vector<Token> out;
  int line = 0;
  size_t seen = 0;
  for (auto raw : split_lines(text)) {
    ++line;
    const auto t = trim(raw);
    if (t.empty() || t[0] == '#') continue;
    if (seen++ < skip_lines) continue;
    for (auto f : split_fields(t, delimiters)) out.push_back({line, std::string(f)});
  }
  return out;
}

// hc in eV·nm (CODATA 2018, exact in SI): λ[nm] = 1239.841984 / E[eV].
constexpr double kHcEvNm = 1239.841984;

double sopra_lambda_nm(int unit, double x) {
  switch (unit) {
    case 1:
      return kHcEvNm / x;
    case 2:
      return x * kNmPerUm;
    case 3:
      return 1e7 / x;  // cm⁻¹: 10⁷ nm per cm
    default:
      return x;
  }
}

struct SopraHeader {
  int unit = 0, intervals = 0, line = 0;
  double first = 0, last = 0;
};

SopraHeader sopra_header(const std::string& path, std::string_view text) {
  const auto t = tokens(text, 0, " \t;,");
  SopraHeader h;
  std::vector<double> v;
  for (const auto& tok : t) {
    if (tok.line != t.front().line) break;
    double x;
    if (!parse_finite(tok.text, x))
      throw InputError(path, tok.line,
                       fmt::format("SOPRA first line: '{}' is not a number", tok.text));
    v.push_back(x);
  }
  h.line = t.front().line;
  const char* form =
      "expected the SOPRA first line 'UNIT FIRST LAST INTERVALS' (UNIT 1 eV, 2 um, 3 1/cm, 4 nm)";
  if (v.size() != 4)
    throw InputError(path, h.line, fmt::format("{}, found {} numbers", form, v.size()));
  if (v[0] != std::floor(v[0]) || v[0] < 1 || v[0] > 4)
    throw InputError(
        path, h.line,
        fmt::format("SOPRA unit code {:g} must be 1 (eV), 2 (um), 3 (1/cm) or 4 (nm)", v[0]));
  if (v[3] != std::floor(v[3]) || v[3] < 1 || v[3] > 1e6)
    throw InputError(
        path, h.line,
        fmt::format("SOPRA interval count {:g} must be an integer from 1 to 1000000", v[3]));
  if (!(v[1] > 0) || !(v[2] > 0) || v[1] == v[2])
    throw InputError(path, h.line, "SOPRA first and last values must be positive and different");
  h.unit = static_cast<int>(v[0]);
  h.first = v[1];
  h.last = v[2];
  h.intervals = static_cast<int>(v[3]);
  return h;
}

}  // namespace

OpticalConstants read_sopra_nk(const std::string& path, const UsedRange& used) {
  const std::string text = read_text_file(path);
  const auto first = tokens(text, 0, " \t;,");
  double x;
  if (first.empty() || !parse_finite(first.front().text, x)) return read_nk_table(path, used);
  const SopraHeader h = sopra_header(path, text);
  const auto values = tokens(text, 1, " \t;,");
  const size_t points = static_cast<size_t>(h.intervals) + 1;
  if (values.size() != 2 * points)
    throw InputError(path, values.empty() ? h.line : values.back().line,
                     fmt::format("expected {} values ({} n, k pairs), found {}", 2 * points, points,
                                 values.size()));
  // Rows in increasing wavelength: energies and wavenumbers list them the other way.
  const bool reverse = sopra_lambda_nm(h.unit, h.last) < sopra_lambda_nm(h.unit, h.first);
  TabulatedRows rows(path, DispersionBlock::Kind::TabulatedNK, h.line);
  for (size_t j = 0; j < points; ++j) {
    const size_t i = reverse ? points - 1 - j : j;
    const double lambda_nm =
        sopra_lambda_nm(h.unit, h.first + (h.last - h.first) * double(i) / h.intervals);
    double n, k;
    const auto& tn = values[2 * i];
    const auto& tk = values[2 * i + 1];
    if (!parse_finite(tn.text, n) || !parse_finite(tk.text, k))
      rows.add_defect(tn.line, lambda_nm,
                      fmt::format("'{} {}' is not a pair of numbers", tn.text, tk.text));
    else
      rows.add(tn.line, lambda_nm, n, k);
  }
  OpticalConstants oc;
  oc.file = path;
  oc.blocks.push_back(rows.finish(used, oc.warnings));
  return oc;
}

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

DispersionBlock read_spd(const std::string& path, DispersionBlock::Kind kind, const UsedRange& used,
                         std::vector<std::string>& warnings) {
  const auto t = tokens(read_text_file(path), 0, " \t,");
  if (t.empty()) throw InputError(path, 0, "no wavelength, value pairs");
  if (t.size() % 2)
    throw InputError(path, t.back().line,
                     "odd number of values: expected wavelength (nm), value pairs");
  TabulatedRows rows(path, kind, t.front().line);
  for (size_t i = 0; i < t.size(); i += 2) {
    double lambda_nm, v;
    if (!parse_finite(t[i].text, lambda_nm))
      throw InputError(path, t[i].line,
                       fmt::format("wavelength '{}' is not a finite number", t[i].text));
    if (!parse_finite(t[i + 1].text, v))
      rows.add_defect(t[i + 1].line, lambda_nm,
                      fmt::format("'{}' is not a finite number", t[i + 1].text));
    else
      rows.add(t[i].line, lambda_nm, v, v);
  }
  return rows.finish(used, warnings);
}

}  // namespace

OpticalConstants read_spd_pair(const std::string& path, const UsedRange& used) {
  std::string stem;
  if (ends_with(path, ".eta.spd"))
    stem = path.substr(0, path.size() - 8);
  else if (ends_with(path, ".k.spd"))
    stem = path.substr(0, path.size() - 6);
  else
    throw InputError(path, 0,
                     "an .spd input is one file of a pair: NAME.eta.spd (n) and NAME.k.spd (k)");
  const std::string eta = stem + ".eta.spd", k = stem + ".k.spd";
  std::error_code ec;
  if (!std::filesystem::exists(eta, ec))
    throw InputError(eta, 0, "no such file (the n half of the .spd pair)");
  OpticalConstants oc;
  oc.file = eta;
  oc.blocks.push_back(read_spd(eta, DispersionBlock::Kind::TabulatedN, used, oc.warnings));
  if (std::filesystem::exists(k, ec))
    oc.blocks.push_back(read_spd(k, DispersionBlock::Kind::TabulatedK, used, oc.warnings));
  return oc;
}

namespace {

// A user's table of n without k whose n drops below 1 in the visible (380-780 nm) is a metal's or
// a semiconductor's n with its k left behind: no lossless material has a phase index below 1
// there, and read as one it would be a "dielectric" of F0 ≈ 0.16. InputError naming what is
// missing.
void require_k_where_n_below_one(const OpticalConstants& oc, bool spd_pair) {
  for (const auto& b : oc.blocks)
    if (b.kind != DispersionBlock::Kind::TabulatedN) return;
  for (const auto& b : oc.blocks)
    for (std::size_t i = 0; i < b.lambda_nm.size(); ++i)
      if (b.lambda_nm[i] >= 380 && b.lambda_nm[i] <= 780 && b.n[i] < 1)
        throw InputError(
            oc.file, b.line,
            fmt::format("n is {:g} at {:g} nm and there is no k: no lossless material has n below "
                        "1 in the visible, so this is an absorbing material's n without its k ({})",
                        b.n[i], b.lambda_nm[i],
                        spd_pair ? "add NAME.k.spd beside NAME.eta.spd"
                                 : "add a k column: wavelength, n, k"));
}

}  // namespace

OpticalConstants read_optical_file(const std::string& path, const UsedRange& used) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".yml" || ext == ".yaml") return read_refractiveindex_file(path, used);
  if (ext == ".nk") return read_sopra_nk(path, used);
  OpticalConstants oc = ext == ".spd" ? read_spd_pair(path, used) : read_nk_table(path, used);
  require_k_where_n_below_one(oc, ext == ".spd");
  return oc;
}

}  // namespace fl::spectral
