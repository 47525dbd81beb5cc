#include "spectral/nk_columns.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "spectral/text_file.h"
#include "util/errors.h"

namespace fl::spectral::nk {
namespace {

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

}  // namespace

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

namespace {

// A field that is only a unit ("(nm)", "µm") belongs to the column before it: "wavelength (nm)"
// split on whitespace, or "Wavelength, µm" split on its comma.
bool unit_only(std::string_view field) {
  const auto words = name_words(field);
  return words.size() == 1 && unit_word(words.front()) > 0;
}

}  // namespace

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

}  // namespace fl::spectral::nk
