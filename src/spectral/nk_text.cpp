#include "spectral/nk_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
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
enum class Separator { Comma, Semicolon, Tab, Whitespace };

// hc in eV·nm (CODATA 2018, exact in SI: h = 6.62607015e-34 J s, c = 299792458 m/s,
// e = 1.602176634e-19 C): λ[nm] = 1239.841984 / E[eV].
constexpr double kHcEvNm = 1239.841984;

struct HeaderColumn {
  Role role;
  std::string name;        // as written (trimmed)
  double nm_per_unit = 0;  // wavelength column: 1 (nm), 1000 (µm); 0 when the name gives no unit
  bool energy_ev = false;  // the "wavelength" column holds photon energies in eV: λ = hc / E
};

struct Header {
  Separator separator = Separator::Comma;
  std::vector<HeaderColumn> columns;
  int wavelength = -1, n = -1, k = -1;  // column indices
  int line = 0;
};

// Lower-case ASCII words of a column name; µ (U+00B5), μ (U+03BC) become u and λ (U+03BB) lambda.
// A byte 0xB5 that continues no UTF-8 sequence is Windows-1252's (and Latin-1's) µ: also u.
std::vector<std::string> name_words(std::string_view name) {
  std::string s;
  int continuation = 0;  // bytes still owed to the UTF-8 sequence being read
  for (size_t i = 0; i < name.size(); ++i) {
    const auto c = static_cast<unsigned char>(name[i]);
    const auto next = i + 1 < name.size() ? static_cast<unsigned char>(name[i + 1]) : 0;
    if ((c == 0xC2 && next == 0xB5) || (c == 0xCE && next == 0xBC)) {
      s += 'u', ++i;
    } else if (c == 0xCE && next == 0xBB) {
      s += " lambda ", ++i;
    } else if (c >= 0x80 && c < 0xC0 && continuation > 0) {
      s += ' ', --continuation;
    } else {
      continuation = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
      s += c == 0xB5 ? 'u' : std::isalnum(c) ? static_cast<char>(std::tolower(c)) : ' ';
    }
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

bool has_word(const std::vector<std::string>& words, std::string_view w) {
  return std::find(words.begin(), words.end(), w) != words.end();
}

// A photon-energy column: `eV`, `E (eV)`, `energy_eV`, `Photon energy [eV]`, `hv (eV)`. An energy
// column without its unit is refused rather than guessed.
std::optional<HeaderColumn> energy_column(const std::string& file, int line, std::string_view field,
                                          const std::vector<std::string>& words) {
  const std::string& w = words.front();
  const bool named = w == "energy" || w == "photon" || w == "e" || w == "hv" || w == "hnu";
  if (!(words.size() == 1 && w == "ev") && !(named && has_word(words, "ev"))) {
    if (named && w != "e")
      throw InputError(file, line,
                       fmt::format("column '{}' names no unit: write 'energy (eV)' for photon "
                                   "energies in eV, or a wavelength column with its unit",
                                   trim(field)));
    return std::nullopt;
  }
  return HeaderColumn{Role::Wavelength, std::string(trim(field)), 0.0, true};
}

std::optional<HeaderColumn> header_column(const std::string& file, int line,
                                          std::string_view field) {
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
  if (auto e = energy_column(file, line, field, words)) return e;
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
  const char delim = sep == Separator::Comma ? ',' : sep == Separator::Semicolon ? ';' : '\t';
  std::string cur;
  bool quoted = false;
  for (const char c : line) {
    if (c == '"' && sep != Separator::Tab)
      quoted = !quoted;
    else if (c == delim && !quoted)
      out.emplace_back(trim(cur)), cur.clear();
    else
      cur += c;
  }
  out.emplace_back(trim(cur));
  return out;
}

// A semicolon separates columns wherever it appears (spreadsheets in locales whose decimal mark is
// a comma write "400;0,5;2,1").
Separator separator_of(std::string_view line) {
  if (line.find(';') != std::string_view::npos) return Separator::Semicolon;
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
  auto split = split_line(text, h.separator);
  if (split.size() > 1 && split.back().empty())
    split.pop_back();  // "wl,n,k,": a trailing separator
  for (auto& f : split) {
    if (unit_only(f) && !fields.empty())
      fields.back() += " " + f;
    else
      fields.push_back(std::move(f));
  }
  for (const auto& f : fields) {
    const auto c = header_column(file, line, f);
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

// The decimal mark of a file's numbers. A field "0,5" is a decimal comma wherever the comma does
// not separate columns (semicolon-, tab- or whitespace-separated, or a quoted CSV field); a file
// uses one mark throughout, since "1,234" beside "0.5" could be a thousands separator.
struct DecimalMark {
  char mark = 0;  // '.' or ',' once a number with a fraction was read
  int line = 0;   // where
};

// "0,5", "-1,25e-3": digits, one comma, digits, an optional exponent; the comma made a point.
std::optional<std::string> decimal_comma_form(std::string_view field) {
  const auto comma = field.find(',');
  if (comma == std::string_view::npos || field.find(',', comma + 1) != std::string_view::npos ||
      field.find('.') != std::string_view::npos)
    return std::nullopt;
  const auto digit = [&](size_t i) {
    return i < field.size() && std::isdigit(static_cast<unsigned char>(field[i]));
  };
  if (comma == 0 || !digit(comma - 1) || !digit(comma + 1)) return std::nullopt;
  std::string out(field);
  out[comma] = '.';
  return out;
}

// parse_finite with decimal commas; InputError when `dm`'s file (or column: `scope`) has used the
// other mark before.
bool parse_number(std::string_view raw, DecimalMark& dm, const std::string& file, int line,
                  double& v, const char* scope = "file") {
  const auto field = trim(raw);
  const auto comma_form = decimal_comma_form(field);
  const char mark = comma_form ? ',' : field.find('.') != std::string_view::npos ? '.' : 0;
  if (!parse_finite(comma_form ? std::string_view(*comma_form) : field, v)) return false;
  if (mark && dm.mark && mark != dm.mark)
    throw InputError(file, line,
                     fmt::format("'{}' has a decimal {} but line {} has a decimal {}: a {} must "
                                 "use one decimal mark ('1,234' could be a thousands separator)",
                                 field, mark == ',' ? "comma" : "point", dm.line,
                                 dm.mark == ',' ? "comma" : "point", scope));
  if (mark && !dm.mark) dm = {mark, line};
  return true;
}

struct Section {
  Header header;
  std::vector<TabulatedRow> rows;  // as read; TabulatedRows judges them in wavelength order
  bool epsilon = false;            // the n and k columns hold ε1 and ε2 (WVASE's E1E2)
  // Between semicolons a comma separates no thousands in numbers of this kind, so there each
  // column keeps its own mark ("300.9;1,4;1,679": the wavelength with a point, n and k with
  // commas).
  DecimalMark column_marks[3];  // wavelength, n, k
};

// A data row: its first field is a number, split as the line's own separator suggests or, for
// "400\t0,5\t2,1" (decimal commas between tabs or spaces), on whitespace; or the line starts like
// one ("1.234,5;..."), so that the row, not a header, is reported.
bool starts_with_number(std::string_view line) {
  const auto digit = [&](size_t i) {
    return i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]));
  };
  if (line.empty()) return false;
  if (digit(0) || ((line[0] == '-' || line[0] == '+' || line[0] == '.') && digit(1))) return true;
  for (const Separator sep : {separator_of(line), Separator::Whitespace}) {
    const auto fields = split_line(line, sep);
    double v;
    DecimalMark dm;
    if (!fields.empty() && parse_number(fields.front(), dm, "", 0, v)) return true;
  }
  return false;
}

double nm_per_unit(const Header& h) {
  const double u = h.columns[h.wavelength].nm_per_unit;
  return u > 0 ? u : 1.0;
}

// n + ik from the permittivity ε1 + iε2 = (n + ik)², the root with n ≥ 0 (k takes ε2's sign).
void n_k_from_epsilon(double e1, double e2, double& n, double& k) {
  const double m = std::hypot(e1, e2);
  if (e1 >= 0) {
    n = std::sqrt((m + e1) / 2);
    k = n > 0 ? e2 / (2 * n) : 0.0;
  } else {
    k = std::copysign(std::sqrt((m - e1) / 2), e2);
    n = e2 / (2 * k);
  }
}

// The row's wavelength in nm from its first column: a wavelength in the column's unit, or a photon
// energy in eV (λ = hc / E). InputError when there is none.
double row_lambda_nm(const Section& s, const std::string& file, int line, double x) {
  const auto& col = s.header.columns[s.header.wavelength];
  if (!col.energy_ev) return x * nm_per_unit(s.header);
  const double lambda_nm = kHcEvNm / x;
  if (!(x > 0) || !std::isfinite(lambda_nm))
    throw InputError(
        file, line,
        fmt::format("column '{}': photon energy {:g} eV must be positive", col.name, x));
  return lambda_nm;
}

// A field with both '.' and ',' ("1.234,5", "400,0.5,2.0") holds a thousands separator or
// columns split by ',' where the header splits them otherwise: the message says both.
std::string not_a_number(const std::string& column, const std::string& field) {
  const bool both = field.find('.') != std::string::npos && field.find(',') != std::string::npos;
  return fmt::format("column '{}': '{}' is not a finite number{}", column, field,
                     both ? " (with both '.' and ',' it holds a thousands separator, which is not "
                            "read, or columns separated by ',' unlike the header's)"
                          : "");
}

void add_table_row(Section& s, DecimalMark& dm, const std::string& file, int line,
                   std::string_view text) {
  const Header& h = s.header;
  auto f = split_line(text, h.separator);
  if (f.size() == h.columns.size() + 1 && f.back().empty()) f.pop_back();  // "400,0.5,2.1,"
  const auto field = [&](int c) { return c < static_cast<int>(f.size()) ? f[c] : std::string(); };
  const bool by_column = h.separator == Separator::Semicolon;
  const auto mark = [&](int i) -> DecimalMark& { return by_column ? s.column_marks[i] : dm; };
  const char* scope = by_column ? "column" : "file";
  double v[3] = {0, 0, 0};  // wavelength, n, k
  if (!parse_number(field(h.wavelength), mark(0), file, line, v[0], scope))
    throw InputError(file, line, not_a_number(h.columns[h.wavelength].name, field(h.wavelength)));
  const double lambda_nm = row_lambda_nm(s, file, line, v[0]);
  const auto defect = [&](std::string problem) {
    s.rows.push_back({line, lambda_nm, 0, 0, std::move(problem)});
  };
  if (f.size() != h.columns.size())
    return defect(fmt::format("expected {} columns, found {}{}", h.columns.size(), f.size(),
                              h.separator == Separator::Comma && f.size() > h.columns.size()
                                  ? " (with decimal commas, separate the columns with ';' or tabs)"
                                  : ""));
  for (int i : {1, 2})
    if (const int c = i == 1 ? h.n : h.k;
        c >= 0 && !parse_number(field(c), mark(i), file, line, v[i], scope))
      return defect(not_a_number(h.columns[c].name, field(c)));
  if (s.epsilon) n_k_from_epsilon(v[1], v[2], v[1], v[2]);
  s.rows.push_back({line, lambda_nm, v[1], v[2], ""});
}

// The section's rows for the judge, in file order, or reversed when they run from long to short
// wavelengths (energies listed upwards).
DispersionBlock finish_section(const Section& s, const std::string& file, const UsedRange& used,
                               std::vector<std::string>& warnings) {
  TabulatedRows rows(file, kind_of(s.header), s.header.line);
  const bool reverse = s.rows.size() > 1 && s.rows.front().lambda_nm > s.rows.back().lambda_nm;
  for (size_t j = 0; j < s.rows.size(); ++j) {
    const auto& r = s.rows[reverse ? s.rows.size() - 1 - j : j];
    if (r.problem.empty())
      rows.add(r.line, r.lambda_nm, r.n, r.k);
    else
      rows.add_defect(r.line, r.lambda_nm, r.problem);
  }
  return rows.finish(used, warnings);
}

// Energies that miss the used range but, read as wavelengths in nm, would overlap it.
void check_energy_units(const std::string& file, const Header& h, const DispersionBlock& b,
                        const UsedRange& used) {
  const double e_min = kHcEvNm / b.max_nm, e_max = kHcEvNm / b.min_nm;
  if (e_max < used.min_nm || e_min > used.max_nm) return;
  throw InputError(
      file, h.line,
      fmt::format("values {:g}-{:g} read as photon energies in eV ('{}') miss "
                  "{:g}-{:g} nm, but as wavelengths in nm they would overlap it: "
                  "name the column 'wavelength_nm'",
                  e_min, e_max, h.columns[h.wavelength].name, used.min_nm, used.max_nm));
}

// Wavelengths that miss the used range in the header's unit but would overlap it in the other.
void check_units(const std::string& file, const Header& h, const DispersionBlock& b,
                 const UsedRange& used) {
  if (b.max_nm >= used.min_nm && b.min_nm <= used.max_nm) return;
  const auto& col = h.columns[h.wavelength];
  if (col.energy_ev) return check_energy_units(file, h, b, used);
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

OpticalConstants finish_sections(const std::string& path, const std::vector<Section>& sections,
                                 const UsedRange& used) {
  OpticalConstants oc;
  oc.file = path;
  for (const auto& s : sections) {
    if (s.rows.empty()) throw InputError(path, s.header.line, "no data rows under this header");
    oc.blocks.push_back(finish_section(s, path, used, oc.warnings));
    check_units(path, s.header, oc.blocks.back(), used);
  }
  if (std::none_of(oc.blocks.begin(), oc.blocks.end(),
                   [](const DispersionBlock& b) { return b.defines_n(); }))
    throw InputError(path, 0, "no column gives n (only k)");
  return oc;
}

}  // namespace

OpticalConstants read_nk_table(const std::string& path, const UsedRange& used) {
  const std::string text = read_text_file(path);
  const auto lines = split_lines(text);
  std::vector<Section> sections;
  DecimalMark dm;
  for (size_t i = 0; i < lines.size(); ++i) {
    const int line = static_cast<int>(i + 1);
    const auto t = trim(lines[i]);
    if (t.empty() || t[0] == '#') continue;
    if (!starts_with_number(t)) {
      sections.push_back({parse_header(path, line, t), {}});
    } else if (sections.empty()) {
      throw InputError(
          path, line,
          "expected a header line naming the columns (e.g. 'wavelength_nm,n,k'), found numbers");
    } else {
      add_table_row(sections.back(), dm, path, line,
                    lines[i]);  // untrimmed: a trailing tab ends an empty field
    }
  }
  if (sections.empty()) throw InputError(path, 0, "no header line");
  return finish_sections(path, sections, used);
}

namespace {

// ---- WVASE .mat ----

// A MATLAB .mat file (binary: a 128-byte text header "MATLAB 5.0 MAT-file..." then data) shares
// the extension: named as such rather than as "binary data".
void refuse_matlab(const std::string& path) {
  check_input_file(path);
  std::ifstream in(path, std::ios::binary);
  char head[6] = {};
  in.read(head, sizeof head);
  if (in.gcount() == 6 && std::string_view(head, 6) == "MATLAB")
    throw InputError(path, 1,
                     "a MATLAB .mat file (binary), not a J.A. Woollam WVASE material file (a name "
                     "line, a unit line, a type line such as NK, then rows)");
}

// The unit line: the first column's unit.
HeaderColumn wvase_unit(const std::string& path, int line, std::string_view text) {
  std::string u(trim(text));
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return std::tolower(c); });
  HeaderColumn c{Role::Wavelength, fmt::format("wavelength ({})", trim(text)), 0.0};
  if (u == "ev") return {Role::Wavelength, "energy (eV)", 0.0, true};
  if (u == "nm" || u == "nanometers")
    c.nm_per_unit = 1.0;
  else if (u == "um" || u == "\xC2\xB5m" || u == "\xCE\xBCm" || u == "microns")
    c.nm_per_unit = kNmPerUm;
  else if (u == "a" || u == "\xC3\xA5" || u == "angstroms")
    c.nm_per_unit = 0.1;
  else
    throw InputError(
        path, line,
        fmt::format("WVASE unit line '{}': expected nm, eV, um or A (angstroms)", trim(text)));
  return c;
}

struct WvaseType {
  bool epsilon = false;
  int rows = -1;  // a row count written instead of the type (CompleteEASE exports); -1: none
};

WvaseType wvase_type(const std::string& path, int line, std::string_view text) {
  std::string t;
  for (const char c : trim(text))
    if (c != ' ' && c != '\t') t += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (t == "NK") return {};
  if (t == "E1E2") return {true};
  double v;
  if (parse_finite(t, v) && v == std::floor(v) && v >= 1 && v <= 1e7)
    return {false, static_cast<int>(v)};
  throw InputError(path, line,
                   fmt::format("WVASE type line '{}': expected NK (n, k columns) or E1E2 (the "
                               "permittivity's real and imaginary parts)",
                               trim(text)));
}

// The first data row's separator: ';', ',' between numbers without spaces, else whitespace.
Separator wvase_separator(std::string_view row) {
  if (row.find(';') != std::string_view::npos) return Separator::Semicolon;
  if (row.find(',') != std::string_view::npos && row.find_first_of(" \t") == std::string_view::npos)
    return Separator::Comma;
  return Separator::Whitespace;
}

}  // namespace

OpticalConstants read_wvase_mat(const std::string& path, const UsedRange& used) {
  refuse_matlab(path);
  const std::string text = read_text_file(path);
  const auto lines = split_lines(text);
  std::vector<std::pair<int, std::string_view>> head;  // name, unit, type lines
  size_t i = 0;
  for (; i < lines.size() && head.size() < 3; ++i)
    if (!trim(lines[i]).empty()) head.emplace_back(static_cast<int>(i + 1), trim(lines[i]));
  if (head.size() < 3)
    throw InputError(path, head.empty() ? 0 : head.back().first,
                     "expected the WVASE header: a name line, a unit line (nm, eV, um or A) and "
                     "a type line (NK or E1E2), then rows");
  Section s;
  s.header.line = head[2].first;
  s.header.columns = {
      wvase_unit(path, head[1].first, head[1].second), {Role::N, "n"}, {Role::K, "k"}};
  s.header.wavelength = 0, s.header.n = 1, s.header.k = 2;
  const WvaseType type = wvase_type(path, head[2].first, head[2].second);
  if (type.epsilon)
    s.epsilon = true, s.header.columns[1].name = "e1", s.header.columns[2].name = "e2";
  DecimalMark dm;
  for (; i < lines.size(); ++i) {
    const auto t = trim(lines[i]);
    if (t.empty() || t[0] == '#') continue;
    if (s.rows.empty()) s.header.separator = wvase_separator(t);
    add_table_row(s, dm, path, static_cast<int>(i + 1), t);
  }
  if (type.rows >= 0 && static_cast<int>(s.rows.size()) != type.rows)
    throw InputError(
        path, head[2].first,
        fmt::format("the header's row count is {}, but {} rows follow", type.rows, s.rows.size()));
  return finish_sections(path, {s}, used);
}

namespace {

// ---- Value streams (SOPRA, .spd) ----

struct Token {
  int line;
  std::string text;
};

// The values of a SOPRA line: separated by whitespace or ';', where a field "0,5" is a decimal
// comma ("2 0,3 0,8 100", "1,4;1,679"); any other comma separates values ("1.4,1.679", "0.5, 2").
void sopra_fields(std::string_view t, int line, std::vector<Token>& out) {
  for (auto f : split_fields(t, " \t;")) {
    if (auto decimal = decimal_comma_form(f)) {
      out.push_back({line, std::move(*decimal)});
      continue;
    }
    for (auto v : split_fields(f, ",")) out.push_back({line, std::string(v)});
  }
}

// Every field after the first `skip_lines` non-empty, non-comment lines, with its line; with
// `delimiters` null, the fields of SOPRA lines (sopra_fields).
std::vector<Token> tokens(std::string_view text, size_t skip_lines, const char* delimiters) {
  std::vector<Token> out;
  int line = 0;
  size_t seen = 0;
  for (auto raw : split_lines(text)) {
    ++line;
    const auto t = trim(raw);
    if (t.empty() || t[0] == '#') continue;
    if (seen++ < skip_lines) continue;
    if (!delimiters) {
      sopra_fields(t, line, out);
      continue;
    }
    for (auto f : split_fields(t, delimiters)) out.push_back({line, std::string(f)});
  }
  return out;
}

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
  const auto t = tokens(text, 0, nullptr);
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

// The header's last number counts intervals, one less than the points: the usual mistake is to
// write the number of points there.
std::string sopra_count_problem(const SopraHeader& h, size_t found) {
  const size_t points = static_cast<size_t>(h.intervals) + 1;
  return fmt::format(
      "expected {} values ({} n, k pairs), found {}: the first line's count {} is of intervals "
      "between FIRST and LAST, so the file holds {} + 1 points{}",
      2 * points, points, found, h.intervals, h.intervals,
      found == 2 * static_cast<size_t>(h.intervals) && h.intervals > 1
          ? fmt::format(" (for {} points, write {})", h.intervals, h.intervals - 1)
          : "");
}

}  // namespace

OpticalConstants read_sopra_nk(const std::string& path, const UsedRange& used) {
  const std::string text = read_text_file(path);
  const auto first = tokens(text, 0, nullptr);
  double x;
  if (first.empty() || !parse_finite(first.front().text, x)) return read_nk_table(path, used);
  const SopraHeader h = sopra_header(path, text);
  const auto values = tokens(text, 1, nullptr);
  const size_t points = static_cast<size_t>(h.intervals) + 1;
  if (values.size() != 2 * points)
    throw InputError(path, values.empty() ? h.line : values.back().line,
                     sopra_count_problem(h, values.size()));
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
  if (ext == ".mat") return read_wvase_mat(path, used);
  OpticalConstants oc = ext == ".spd" ? read_spd_pair(path, used) : read_nk_table(path, used);
  require_k_where_n_below_one(oc, ext == ".spd");
  return oc;
}

}  // namespace fl::spectral
