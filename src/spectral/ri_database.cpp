#include "spectral/ri_database.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "spectral/errors.h"
#include "spectral/text_file.h"
#include "spectral/yaml_file.h"

namespace fl::spectral {
namespace {

constexpr double kNmPerUm = 1000.0;

// How many coefficients each formula accepts at most (refractiveindex.info uses up to C17).
int max_coefficients(int formula) {
  switch (formula) {
    case 7: return 6;
    case 8: return 4;
    case 9: return 6;
    case 6: return 11;
    default: return 17;
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

// Beyond any material's optical constants at any wavelength (far-infrared metals reach ~10³),
// and far below where n² + κ² would overflow in the Fresnel equations.
constexpr double kMaxOpticalConstant = 1e6;

void check_physical(const std::string& file, int line, double n, double k, bool has_n, bool has_k) {
  if (has_n && !(n > 0.0 && n <= kMaxOpticalConstant))
    throw InputError(file, line, fmt::format("n = {} is not physical (must be in (0, {:g}])", n, kMaxOpticalConstant));
  if (has_k && !(k >= 0.0 && k <= kMaxOpticalConstant))
    throw InputError(file, line, fmt::format("k = {} is not physical (must be in [0, {:g}])", k, kMaxOpticalConstant));
}

DispersionBlock parse_tabulated(const std::string& file, const YAML::Node& block,
                                DispersionBlock::Kind kind, int block_line) {
  DispersionBlock b;
  b.kind = kind;
  b.line = block_line;
  const YAML::Node data = block["data"];
  if (!data || !data.IsScalar()) throw InputError(file, block_line, "tabulated block without 'data'");
  const std::string text = data.as<std::string>();
  // A literal block scalar starts on the line after its key.
  const int first_line = data.Mark().line + 2;
  const size_t columns = kind == DispersionBlock::Kind::TabulatedNK ? 3 : 2;
  int i = 0;
  for (auto raw : split_lines(text)) {
    const int line = first_line + i++;
    if (trim(raw).empty()) continue;
    auto v = parse_numbers(file, line, raw, "data");
    if (v.size() != columns)
      throw InputError(file, line, fmt::format("expected {} columns, found {}", columns, v.size()));
    const double lambda = v[0] * kNmPerUm;
    b.lambda_nm.push_back(lambda);
    double n = 0, k = 0;
    if (kind == DispersionBlock::Kind::TabulatedNK) { n = v[1]; k = v[2]; }
    else if (kind == DispersionBlock::Kind::TabulatedN) n = v[1];
    else k = v[1];
    check_physical(file, line, n, k, kind != DispersionBlock::Kind::TabulatedK,
                   kind != DispersionBlock::Kind::TabulatedN);
    b.n.push_back(n);
    b.k.push_back(k);
    if (b.lambda_nm.size() > 1 && !(b.lambda_nm.back() > b.lambda_nm[b.lambda_nm.size() - 2]))
      throw InputError(file, line, "wavelengths are not strictly increasing");
    if (!(lambda > 0.0)) throw InputError(file, line, "wavelength must be positive");
  }
  if (b.lambda_nm.empty()) throw InputError(file, first_line, "tabulated block has no rows");
  b.min_nm = b.lambda_nm.front();
  b.max_nm = b.lambda_nm.back();
  return b;
}

DispersionBlock parse_formula(const std::string& file, const YAML::Node& block, int formula,
                              int block_line) {
  DispersionBlock b;
  b.kind = DispersionBlock::Kind::Formula;
  b.formula = formula;
  b.line = block_line;
  const YAML::Node coeffs = block["coefficients"];
  const YAML::Node range = block["wavelength_range"];
  if (!coeffs || !coeffs.IsScalar())
    throw InputError(file, block_line, fmt::format("formula {} block without 'coefficients'", formula));
  if (!range || !range.IsScalar())
    throw InputError(file, block_line, fmt::format("formula {} block without 'wavelength_range'", formula));
  const int cline = coeffs.Mark().line + 1;
  b.coefficients = parse_numbers(file, cline, coeffs.as<std::string>(), "coefficients");
  if (b.coefficients.empty() || static_cast<int>(b.coefficients.size()) > max_coefficients(formula))
    throw InputError(file, cline, fmt::format("formula {} takes 1 to {} coefficients, found {}", formula,
                                              max_coefficients(formula), b.coefficients.size()));
  const int rline = range.Mark().line + 1;
  auto r = parse_numbers(file, rline, range.as<std::string>(), "wavelength_range");
  if (r.size() != 2) throw InputError(file, rline, "wavelength_range needs two numbers");
  if (!(r[0] > 0.0) || !(r[1] > r[0]))
    throw InputError(file, rline, "wavelength_range must be positive and increasing");
  b.min_nm = r[0] * kNmPerUm;
  b.max_nm = r[1] * kNmPerUm;
  // The formula must give a physical index over its whole range.
  for (int i = 0; i <= 64; ++i) {
    const double lum = r[0] + (r[1] - r[0]) * i / 64.0;
    const double n = evaluate_formula(formula, b.coefficients, lum);
    if (!std::isfinite(n) || !(n > 0.0) || n > kMaxOpticalConstant)
      throw InputError(file, cline, fmt::format("formula {} gives n = {} at {} um (not physical)", formula, n, lum));
  }
  return b;
}

}  // namespace

// refractiveindex.info, "Dispersion formulas" (database doc/), formulas 1-9; λ in µm. Missing
// trailing coefficients are 0, as in the database's own tools.
double evaluate_formula(int formula, const std::vector<double>& coeffs, double wl) {
  double C[18] = {0};
  for (size_t i = 0; i < coeffs.size() && i < 17; ++i) C[i + 1] = coeffs[i];
  const double wl2 = wl * wl;
  switch (formula) {
    case 1: {  // Sellmeier: n² − 1 = C1 + Σ Ci λ² / (λ² − Ci+1²)
      double s = 1 + C[1];
      for (int i = 2; i <= 16; i += 2) if (C[i] != 0) s += C[i] / (1 - (C[i + 1] / wl) * (C[i + 1] / wl));
      return std::sqrt(s);
    }
    case 2: {  // Sellmeier-2: n² − 1 = C1 + Σ Ci λ² / (λ² − Ci+1)
      double s = 1 + C[1];
      for (int i = 2; i <= 16; i += 2) if (C[i] != 0) s += C[i] / (1 - C[i + 1] / wl2);
      return std::sqrt(s);
    }
    case 3: {  // Polynomial: n² = C1 + Σ Ci λ^Ci+1
      double s = C[1];
      for (int i = 2; i <= 16; i += 2) if (C[i] != 0) s += C[i] * std::pow(wl, C[i + 1]);
      return std::sqrt(s);
    }
    case 4: {  // RefractiveIndex.INFO: two Sellmeier-like terms plus a polynomial
      double s = C[1];
      if (C[2] != 0) s += C[2] * std::pow(wl, C[3]) / (wl2 - std::pow(C[4], C[5]));
      if (C[6] != 0) s += C[6] * std::pow(wl, C[7]) / (wl2 - std::pow(C[8], C[9]));
      for (int i = 10; i <= 16; i += 2) if (C[i] != 0) s += C[i] * std::pow(wl, C[i + 1]);
      return std::sqrt(s);
    }
    case 5: {  // Cauchy: n = C1 + Σ Ci λ^Ci+1
      double s = C[1];
      for (int i = 2; i <= 16; i += 2) if (C[i] != 0) s += C[i] * std::pow(wl, C[i + 1]);
      return s;
    }
    case 6: {  // Gases: n − 1 = C1 + Σ Ci / (Ci+1 − λ⁻²)
      double s = 1 + C[1];
      for (int i = 2; i <= 10; i += 2) if (C[i] != 0) s += C[i] / (C[i + 1] - 1.0 / wl2);
      return s;
    }
    case 7: {  // Herzberger; 0.028 µm² is the formula's fixed pole
      const double d = wl2 - 0.028;
      return C[1] + C[2] / d + C[3] / (d * d) + C[4] * wl2 + C[5] * wl2 * wl2 + C[6] * wl2 * wl2 * wl2;
    }
    case 8: {  // Retro: (n² − 1)/(n² + 2) = C1 + C2 λ²/(λ² − C3) + C4 λ²
      const double t = C[1] + C[2] * wl2 / (wl2 - C[3]) + C[4] * wl2;
      return std::sqrt((2 * t + 1) / (1 - t));
    }
    case 9: {  // Exotic
      const double d = wl - C[5];
      return std::sqrt(C[1] + C[2] / (wl2 - C[3]) + C[4] * d / (d * d + C[6]));
    }
    default:
      return std::nan("");
  }
}

OpticalConstants read_refractiveindex_file(const std::string& path) {
  const YAML::Node root = read_yaml_file(path);
  if (!root.IsMap()) throw InputError(path, 1, "expected a refractiveindex.info YAML map with DATA");
  const YAML::Node data = root["DATA"];
  if (!data) throw InputError(path, 0, "no DATA section");
  if (!data.IsSequence() || data.size() == 0)
    throw InputError(path, data.Mark().line + 1, "DATA must be a non-empty list of blocks");
  OpticalConstants oc;
  oc.file = path;
  try {
    for (const auto& block : data) {
      const int line = block.Mark().line + 1;
      if (!block.IsMap() || !block["type"] || !block["type"].IsScalar())
        throw InputError(path, line, "DATA block without a 'type'");
      const std::string type = block["type"].as<std::string>();
      if (type == "tabulated nk") oc.blocks.push_back(parse_tabulated(path, block, DispersionBlock::Kind::TabulatedNK, line));
      else if (type == "tabulated n") oc.blocks.push_back(parse_tabulated(path, block, DispersionBlock::Kind::TabulatedN, line));
      else if (type == "tabulated k") oc.blocks.push_back(parse_tabulated(path, block, DispersionBlock::Kind::TabulatedK, line));
      else if (type.rfind("formula ", 0) == 0) {
        const std::string num = type.substr(8);
        if (num.size() != 1 || num[0] < '1' || num[0] > '9')
          throw InputError(path, line, fmt::format("unknown formula type '{}' (expected formula 1 to 9)", type));
        oc.blocks.push_back(parse_formula(path, block, num[0] - '0', line));
      } else {
        throw InputError(path, line, fmt::format("unknown DATA block type '{}'", type));
      }
    }
  } catch (const YAML::Exception& e) {
    throw InputError(path, e.mark.line + 1, "malformed DATA: " + e.msg);
  }
  bool has_n = false;
  for (const auto& b : oc.blocks) has_n |= b.defines_n();
  if (!has_n) throw InputError(path, 0, "no block defines n (only k data)");
  return oc;
}

OpticalConstants read_nk_csv(const std::string& path) {
  const std::string text = read_text_file(path);
  const auto lines = split_lines(text);
  size_t i = 0;
  while (i < lines.size() && (trim(lines[i]).empty() || trim(lines[i])[0] == '#')) ++i;
  if (i == lines.size()) throw InputError(path, 0, "no header line");
  std::vector<std::string> header;
  for (auto f : split_fields(lines[i], ",")) header.emplace_back(trim(f));
  const bool with_k = header == std::vector<std::string>{"lambda_nm", "n", "k"};
  if (!with_k && header != std::vector<std::string>{"lambda_nm", "n"})
    throw InputError(path, static_cast<int>(i + 1), "header must be 'lambda_nm,n,k' (or 'lambda_nm,n')");
  DispersionBlock b;
  b.kind = with_k ? DispersionBlock::Kind::TabulatedNK : DispersionBlock::Kind::TabulatedN;
  b.line = static_cast<int>(i + 1);
  for (++i; i < lines.size(); ++i) {
    const int line = static_cast<int>(i + 1);
    const auto t = trim(lines[i]);
    if (t.empty() || t[0] == '#') continue;
    std::vector<std::string_view> fields;
    size_t start = 0;
    while (true) {  // keep empty fields so that a missing value is reported
      const size_t c = t.find(',', start);
      fields.push_back(t.substr(start, c == std::string_view::npos ? std::string_view::npos : c - start));
      if (c == std::string_view::npos) break;
      start = c + 1;
    }
    if (fields.size() != header.size())
      throw InputError(path, line, fmt::format("expected {} columns, found {}", header.size(), fields.size()));
    double v[3] = {0, 0, 0};
    for (size_t c = 0; c < fields.size(); ++c)
      if (!parse_finite(fields[c], v[c]))
        throw InputError(path, line, fmt::format("column '{}': '{}' is not a finite number", header[c], trim(fields[c])));
    if (!(v[0] > 0.0)) throw InputError(path, line, "wavelength must be positive");
    if (!b.lambda_nm.empty() && !(v[0] > b.lambda_nm.back()))
      throw InputError(path, line, "wavelengths are not strictly increasing");
    check_physical(path, line, v[1], v[2], true, with_k);
    b.lambda_nm.push_back(v[0]);
    b.n.push_back(v[1]);
    b.k.push_back(v[2]);
  }
  if (b.lambda_nm.empty()) throw InputError(path, 0, "no data rows");
  b.min_nm = b.lambda_nm.front();
  b.max_nm = b.lambda_nm.back();
  OpticalConstants oc;
  oc.file = path;
  oc.blocks.push_back(std::move(b));
  return oc;
}

OpticalConstants constant_ior(double n, double k, const std::string& label) {
  check_physical(label, 0, n, k, true, true);
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
      case DispersionBlock::Kind::Constant: return want_n ? b.n[0] : b.k[0];
      case DispersionBlock::Kind::Formula:
        return evaluate_formula(b.formula, b.coefficients,
                                std::clamp(lambda_nm, b.min_nm, b.max_nm) / kNmPerUm);
      default: return interpolate_linear(b.lambda_nm, want_n ? b.n : b.k, lambda_nm);
    }
  }
  double at(double lambda_nm, bool& clamped) const {
    const DispersionBlock* nearest = nullptr;
    double best = 1e300;
    for (const auto* b : blocks) {
      if (lambda_nm >= b->min_nm && lambda_nm <= b->max_nm) { clamped = false; return value_in(*b, lambda_nm); }
      const double d = lambda_nm < b->min_nm ? b->min_nm - lambda_nm : lambda_nm - b->max_nm;
      if (!nearest || d < best) { best = d; nearest = b; }  // d can exceed any bound (λ = 1e300)
    }
    clamped = true;
    return value_in(*nearest, lambda_nm);
  }
};

}  // namespace

SampledIor sample_ior(const OpticalConstants& oc, const SpectralGrid& grid, const std::string& label) {
  SampledIor out;
  out.ior.grid = grid;
  out.ior.ior.resize(grid.count);
  QuantitySource n_src{{}, true}, k_src{{}, false};
  for (const auto& b : oc.blocks) {
    if (b.defines_n()) n_src.blocks.push_back(&b);
    if (b.defines_k()) k_src.blocks.push_back(&b);
  }
  if (n_src.blocks.empty()) throw InputError(oc.file, 0, "no n data");
  // Samples one quantity; returns the uncovered wavelength runs ("360-385").
  auto sample = [&](const QuantitySource& src, const char* what, std::vector<double>& values) {
    values.assign(grid.count, 0.0);
    std::vector<std::string> runs;
    if (src.blocks.empty()) return runs;
    int clamped_count = 0, run_start = -1;
    for (int i = 0; i <= grid.count; ++i) {
      bool clamped = false;
      if (i < grid.count) {
        values[i] = src.at(grid.lambda_nm(i), clamped);
        clamped_count += clamped;
      }
      if (clamped && run_start < 0) run_start = i;
      if (!clamped && run_start >= 0) {
        runs.push_back(fmt::format("{:g}-{:g}", grid.lambda_nm(run_start), grid.lambda_nm(i - 1)));
        run_start = -1;
      }
    }
    if (clamped_count == grid.count)
      throw InputError(oc.file, 0, fmt::format("{} data does not cover any of {:g}-{:g} nm", what, grid.start_nm, grid.end_nm()));
    return runs;
  };
  std::vector<double> n, k;
  const auto n_runs = sample(n_src, "n", n);
  const auto k_runs = sample(k_src, "k", k);
  auto warn = [&](const char* what, const std::vector<std::string>& runs) {
    if (!runs.empty())
      out.warnings.push_back(fmt::format("{}: {} data does not cover {} nm; using the nearest value there", label,
                                         what, fmt::join(runs, " and ")));
  };
  if (n_runs == k_runs) {
    warn("n and k", n_runs);
  } else {
    warn("n", n_runs);
    warn("k", k_runs);
  }
  for (int i = 0; i < grid.count; ++i) {
    if (!(n[i] > 0.0) || !std::isfinite(n[i]))
      throw InputError(oc.file, 0, fmt::format("n = {} at {:g} nm is not physical", n[i], grid.lambda_nm(i)));
    out.ior.ior[i] = {n[i], std::max(0.0, k[i])};
  }
  return out;
}

}  // namespace fl::spectral
