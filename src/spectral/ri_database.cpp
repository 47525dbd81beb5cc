#include "spectral/ri_database.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "spectral/tabulated.h"
#include "spectral/text_file.h"
#include "spectral/yaml_file.h"
#include "util/errors.h"

namespace fl::spectral {
namespace {

constexpr double kNmPerUm = 1000.0;

// How many coefficients each formula accepts at most (refractiveindex.info uses up to C17).
int max_coefficients(int formula) {
  switch (formula) {
    case 7:
      return 6;
    case 8:
      return 4;
    case 9:
      return 6;
    case 6:
      return 11;
    default:
      return 17;
  }
}

std::vector<double> parse_numbers(const std::string& file, int line, std::string_view text,
                                  const char* what) {
  std::vector<double> out;
  for (auto f : split_fields(text, " \t,")) {
    double v;
    if (!parse_finite(f, v))
      throw InputError(file, line, fmt::format("{}: '{}' is not a finite number", what, f));
    out.push_back(v);
  }
  return out;
}

// One data line into `rows`: the first field is the wavelength (in µm; an error when it is not a
// number), the others the values; a wrong column count or a value that is not a number is a
// defect of the row, judged where its wavelength lies.
void add_data_line(TabulatedRows& rows, const std::string& file, int line, std::string_view raw,
                   size_t columns) {
  std::array<std::string_view, 3> fields;
  const size_t count = split_fields(raw, " \t,", fields);
  double lambda_um = 0;
  if (!parse_finite(fields.front(), lambda_um))
    throw InputError(file, line, fmt::format("data: '{}' is not a finite number", fields.front()));
  const double lambda_nm = lambda_um * kNmPerUm;
  if (count != columns)
    return rows.add_defect(line, lambda_nm,
                           fmt::format("expected {} columns, found {}", columns, count));
  double v[3] = {lambda_um, 0, 0};
  for (size_t c = 1; c < columns; ++c)
    if (!parse_finite(fields[c], v[c]))
      return rows.add_defect(line, lambda_nm,
                             fmt::format("data: '{}' is not a finite number", fields[c]));
  const bool nk = columns == 3;
  rows.add(line, lambda_nm, v[1], nk ? v[2] : v[1]);
}

DispersionBlock parse_tabulated(const std::string& file, const YamlNode& block,
                                DispersionBlock::Kind kind, int block_line, const UsedRange& used,
                                std::vector<std::string>& warnings) {
  const YamlNode& data = block["data"];
  if (!data.is_scalar()) throw InputError(file, block_line, "tabulated block without 'data'");
  const std::string& text = data.scalar();
  // A literal block scalar starts on the line after its key.
  const int first_line = data.line() + 2;
  const size_t columns = kind == DispersionBlock::Kind::TabulatedNK ? 3 : 2;
  TabulatedRows rows(file, kind, first_line);
  int i = 0;
  for (auto raw : split_lines(text)) {
    const int line = first_line + i++;
    if (!trim(raw).empty()) add_data_line(rows, file, line, raw, columns);
  }
  if (rows.empty()) throw InputError(file, first_line, "tabulated block has no rows");
  auto b = rows.finish(used, warnings);
  b.line = block_line;
  return b;
}

// The formula must give a physical index wherever it is read: over its range's overlap with the
// used range at every nm (the finest grid step) and at the overlap's ends, or at the one end of its
// range that the nearest-value rule reads when they do not overlap.
void check_formula(const std::string& file, int line, const DispersionBlock& b,
                   const UsedRange& used) {
  double lo = std::max(b.min_nm, used.min_nm), hi = std::min(b.max_nm, used.max_nm);
  if (lo > hi) lo = hi = b.max_nm < used.min_nm ? b.max_nm : b.min_nm;
  std::vector<double> at{lo, hi};
  for (double nm = std::ceil(lo); nm <= hi; nm += 1.0) at.push_back(nm);
  for (double nm : at) {
    const double n = evaluate_formula(b.formula, b.coefficients, nm / kNmPerUm);
    if (!std::isfinite(n) || !(n > 0.0) || n > kMaxOpticalConstant)
      throw InputError(file, line,
                       fmt::format("formula {} gives n = {} at {:g} um (not physical)", b.formula,
                                   std::isnan(n) ? "nan" : fmt::format("{}", n), nm / kNmPerUm));
  }
}

DispersionBlock parse_formula(const std::string& file, const YamlNode& block, int formula,
                              int block_line, const UsedRange& used) {
  DispersionBlock b;
  b.kind = DispersionBlock::Kind::Formula;
  b.formula = formula;
  b.line = block_line;
  const YamlNode& coeffs = block["coefficients"];
  const YamlNode& range = block["wavelength_range"];
  if (!coeffs.is_scalar())
    throw InputError(file, block_line,
                     fmt::format("formula {} block without 'coefficients'", formula));
  if (!range.is_scalar())
    throw InputError(file, block_line,
                     fmt::format("formula {} block without 'wavelength_range'", formula));
  const int cline = coeffs.line() + 1;
  b.coefficients = parse_numbers(file, cline, coeffs.scalar(), "coefficients");
  if (b.coefficients.empty() || static_cast<int>(b.coefficients.size()) > max_coefficients(formula))
    throw InputError(file, cline,
                     fmt::format("formula {} takes 1 to {} coefficients, found {}", formula,
                                 max_coefficients(formula), b.coefficients.size()));
  const int rline = range.line() + 1;
  auto r = parse_numbers(file, rline, range.scalar(), "wavelength_range");
  if (r.size() != 2) throw InputError(file, rline, "wavelength_range needs two numbers");
  if (!(r[0] > 0.0) || !(r[1] > r[0]))
    throw InputError(file, rline, "wavelength_range must be positive and increasing");
  b.min_nm = r[0] * kNmPerUm;
  b.max_nm = r[1] * kNmPerUm;
  check_formula(file, cline, b, used);
  return b;
}

// A page's REFERENCES as one line of plain text: HTML tags removed, whitespace runs collapsed.
std::string plain_reference(const YamlNode& root) {
  const YamlNode& r = root["REFERENCES"];
  if (!r.is_scalar()) return {};
  std::string out;
  bool in_tag = false, space = false;
  for (const char c : r.scalar()) {
    if (c == '<')
      in_tag = true;
    else if (c == '>')
      in_tag = false;
    else if (!in_tag && std::isspace(static_cast<unsigned char>(c)))
      space = !out.empty();
    else if (!in_tag) {
      if (space) out += ' ';
      out += c;
      space = false;
    }
  }
  return out;
}

}  // namespace

namespace {

DispersionBlock parse_block(const std::string& path, const YamlNode& block, const UsedRange& used,
                            std::vector<std::string>& warnings) {
  using Kind = DispersionBlock::Kind;
  const int line = block.line() + 1;
  if (!block.is_map() || !block["type"].is_scalar())
    throw InputError(path, line, "DATA block without a 'type'");
  const std::string& type = block["type"].scalar();
  if (type == "tabulated nk")
    return parse_tabulated(path, block, Kind::TabulatedNK, line, used, warnings);
  if (type == "tabulated n")
    return parse_tabulated(path, block, Kind::TabulatedN, line, used, warnings);
  if (type == "tabulated k")
    return parse_tabulated(path, block, Kind::TabulatedK, line, used, warnings);
  if (type.rfind("formula ", 0) == 0) {
    const std::string num = type.substr(8);
    if (num.size() != 1 || num[0] < '1' || num[0] > '9')
      throw InputError(path, line,
                       fmt::format("unknown formula type '{}' (expected formula 1 to 9)", type));
    return parse_formula(path, block, num[0] - '0', line, used);
  }
  if (type == "tabulated n2")
    throw InputError(path, line,
                     "DATA block type 'tabulated n2' is a nonlinear index, not n, k data");
  throw InputError(path, line, fmt::format("unknown DATA block type '{}'", type));
}

}  // namespace

OpticalConstants read_refractiveindex_file(const std::string& path, const UsedRange& used) {
  const YamlNode root = read_yaml_file(path);
  if (!root.is_map())
    throw InputError(path, 1, "expected a refractiveindex.info YAML map with DATA");
  const YamlNode& data = root["DATA"];
  if (!data) throw InputError(path, 0, "no DATA section");
  if (!data.is_sequence() || data.size() == 0)
    throw InputError(path, data.line() + 1, "DATA must be a non-empty list of blocks");
  OpticalConstants oc;
  oc.file = path;
  for (const auto& block : data.items())
    oc.blocks.push_back(parse_block(path, block, used, oc.warnings));
  oc.reference = plain_reference(root);
  bool has_n = false;
  for (const auto& b : oc.blocks) has_n |= b.defines_n();
  if (!has_n) throw InputError(path, 0, "no block defines n (only k data)");
  return oc;
}

OpticalConstants constant_ior(double n, double k, const std::string& label) {
  if (const auto problem = value_problem(n, k, true, true); !problem.empty())
    throw InputError(label, 0, problem);
  DispersionBlock b;
  b.kind = DispersionBlock::Kind::Constant;
  b.min_nm = 0.0;
  b.max_nm = 1e9;
  b.n = {n};
  b.k = {k};
  OpticalConstants oc;
  oc.file = label;
  oc.blocks.push_back(std::move(b));
  return oc;
}

namespace {

// Value of one quantity (n or k) from the blocks that define it: inside a block's range that
// block, outside every range the nearest block end.
struct QuantitySource {
  std::vector<const DispersionBlock*> blocks;
  bool want_n;

  double value_in(const DispersionBlock& b, double lambda_nm) const {
    switch (b.kind) {
      case DispersionBlock::Kind::Constant:
        return want_n ? b.n[0] : b.k[0];
      case DispersionBlock::Kind::Formula:
        return evaluate_formula(b.formula, b.coefficients,
                                std::clamp(lambda_nm, b.min_nm, b.max_nm) / kNmPerUm);
      default:
        return interpolate_linear(b.lambda_nm, want_n ? b.n : b.k, lambda_nm);
    }
  }
  double at(double lambda_nm, bool& clamped) const {
    const DispersionBlock* nearest = nullptr;
    double best = 1e300;
    for (const auto* b : blocks) {
      if (lambda_nm >= b->min_nm && lambda_nm <= b->max_nm) {
        clamped = false;
        return value_in(*b, lambda_nm);
      }
      const double d = lambda_nm < b->min_nm ? b->min_nm - lambda_nm : lambda_nm - b->max_nm;
      if (!nearest || d < best) {
        best = d;
        nearest = b;
      }  // d can exceed any bound (λ = 1e300)
    }
    clamped = true;
    return value_in(*nearest, lambda_nm);
  }
};

}  // namespace

namespace {

// Samples one quantity on the grid into `values` and `measured`; returns the held runs ("360-385").
std::vector<std::string> sample_quantity(const QuantitySource& src, const SpectralGrid& grid,
                                         std::vector<double>& values, std::vector<bool>& measured) {
  values.assign(grid.count, 0.0);
  measured.assign(grid.count, false);
  std::vector<std::string> runs;
  if (src.blocks.empty()) return runs;
  int run_start = -1;
  for (int i = 0; i <= grid.count; ++i) {
    bool clamped = false;
    if (i < grid.count) {
      values[i] = src.at(grid.lambda_nm(i), clamped);
      measured[i] = !clamped;
    }
    if (clamped && run_start < 0) run_start = i;
    if (!clamped && run_start >= 0) {
      runs.push_back(run_start == i - 1 ? fmt::format("{:g}", grid.lambda_nm(run_start))
                                        : fmt::format("{:g}-{:g}", grid.lambda_nm(run_start),
                                                      grid.lambda_nm(i - 1)));
      run_start = -1;
    }
  }
  return runs;
}

}  // namespace

SampledIor sample_ior(const OpticalConstants& oc, const SpectralGrid& grid,
                      const std::string& label) {
  SampledIor out;
  out.ior.grid = grid;
  out.ior.ior.resize(grid.count);
  QuantitySource n_src{{}, true}, k_src{{}, false};
  for (const auto& b : oc.blocks) {
    if (b.defines_n()) n_src.blocks.push_back(&b);
    if (b.defines_k()) k_src.blocks.push_back(&b);
  }
  if (n_src.blocks.empty()) throw InputError(oc.file, 0, "no n data");
  out.has_k_data = !k_src.blocks.empty();
  std::vector<double> n, k;
  const auto n_runs = sample_quantity(n_src, grid, n, out.n_measured);
  const auto k_runs = sample_quantity(k_src, grid, k, out.k_measured);
  // Without any n in the range there is nothing to compute. A single n inside it (one row at the
  // sodium D line) is an index held constant; k known only outside it (a glass's k tabulated in the
  // infrared) is held like any uncovered stretch; the coverage says so.
  if (std::none_of(n_src.blocks.begin(), n_src.blocks.end(), [&](const DispersionBlock* b) {
        return b->max_nm >= grid.start_nm && b->min_nm <= grid.end_nm();
      }))
    throw InputError(
        oc.file, 0,
        fmt::format("n data does not cover any of {:g}-{:g} nm", grid.start_nm, grid.end_nm()));
  auto describe = [](const char* what, const std::vector<std::string>& runs) {
    return runs.empty()
               ? std::string()
               : fmt::format("{} data does not cover {} nm", what, fmt::join(runs, " and "));
  };
  std::vector<std::string> parts;
  if (n_runs == k_runs)
    parts.push_back(describe("n and k", n_runs));
  else
    parts = {describe("n", n_runs), describe("k", k_runs)};
  for (const auto& p : parts)
    if (!p.empty()) {
      out.warnings.push_back(fmt::format("{}: {}; using the nearest value there", label, p));
      out.uncovered += (out.uncovered.empty() ? "" : "; ") + p;
    }
  for (int i = 0; i < grid.count; ++i) {
    if (!(n[i] > 0.0) || !std::isfinite(n[i]))
      throw InputError(oc.file, 0,
                       fmt::format("n = {} at {:g} nm is not physical", n[i], grid.lambda_nm(i)));
    out.ior.ior[i] = {n[i], std::max(0.0, k[i])};
  }
  return out;
}

}  // namespace fl::spectral
