#include "spectral/nk_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

#include "spectral/nk_columns.h"
#include "spectral/ri_database.h"
#include "spectral/tabulated.h"
#include "spectral/text_file.h"
#include "util/errors.h"

namespace fl::spectral {

using namespace nk;

namespace {

// ---- Tables ----

// The decimal mark of a file's numbers. A field "0,5" is a decimal comma wherever the comma does
// not separate columns (semicolon-, tab- or whitespace-separated, or a quoted CSV field); a file
// uses one mark throughout, since "1,234" beside "0.5" could be a thousands separator.
struct DecimalMark {
  char mark = 0;  // '.' or ',' once a number with a fraction was read
  int line = 0;   // where
};

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

}  // namespace fl::spectral
