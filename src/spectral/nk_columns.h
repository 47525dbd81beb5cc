#pragma once
// The columns of the optical-constant text files: header names (wavelength with its unit, photon
// energy, n, k), separators, decimal commas. Shared by the text readers (nk_text.cpp,
// nk_streams.cpp).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "spectral/ri_database.h"

namespace fl::spectral::nk {

constexpr double kNmPerUm = 1000.0;

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

// Lower-case ASCII words of a column name, the header line's columns, and the fields of a line.
Separator separator_of(std::string_view line);
std::vector<std::string> split_line(std::string_view line, Separator sep);
// InputError naming the file and line for a column that is not a wavelength (with its unit or as
// photon energies in eV), n or k, a quantity given twice, or no wavelength, n or k column.
Header parse_header(const std::string& file, int line, std::string_view text);
DispersionBlock::Kind kind_of(const Header& h);
// "0,5", "-1,25e-3": digits, one comma, digits, an optional exponent; the comma made a point.
std::optional<std::string> decimal_comma_form(std::string_view field);

}  // namespace fl::spectral::nk
