#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

#include "spectral/nk_columns.h"
#include "spectral/nk_text.h"
#include "spectral/ri_database.h"
#include "spectral/tabulated.h"
#include "spectral/text_file.h"
#include "util/errors.h"

namespace fl::spectral {

using namespace nk;

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
