#include "spectral/tabulated.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "util/errors.h"

namespace fl::spectral {

std::string value_problem(double n, double& k, bool has_n, bool has_k) {
  if (has_n && !(n > 0.0 && n <= kMaxOpticalConstant))
    return fmt::format("n = {} is not physical (must be in (0, {:g}])", n, kMaxOpticalConstant);
  if (has_k && k < 0.0 && k > -kNegligibleNegativeK) k = 0.0;
  if (has_k && !(k >= 0.0 && k <= kMaxOpticalConstant))
    return fmt::format("k = {} is not physical (must be in [0, {:g}])", k, kMaxOpticalConstant);
  return {};
}

TabulatedRows::TabulatedRows(std::string file, DispersionBlock::Kind kind, int block_line)
    : file_(std::move(file)), kind_(kind), block_line_(block_line) {}

void TabulatedRows::add(int line, double lambda_nm, double n, double k) {
  if (!(lambda_nm > 0.0)) throw InputError(file_, line, "wavelength must be positive");
  const bool has_n = kind_ != DispersionBlock::Kind::TabulatedK,
             has_k = kind_ != DispersionBlock::Kind::TabulatedN;
  if (!has_n) n = 0.0;
  if (!has_k) k = 0.0;
  std::string problem = value_problem(n, k, has_n, has_k);
  rows_.push_back({line, lambda_nm, n, k, std::move(problem)});
}

void TabulatedRows::add_defect(int line, double lambda_nm, const std::string& problem) {
  if (!(lambda_nm > 0.0)) throw InputError(file_, line, "wavelength must be positive");
  rows_.push_back({line, lambda_nm, 0.0, 0.0, problem});
}

namespace {

std::string nm_text(double nm) {
  return fmt::format("{:g} nm", nm);
}

// The rows in file order split into those kept (strictly increasing wavelengths) and the defects
// (with their problem filled in); exact duplicates of a kept row are counted, not kept.
struct Split {
  std::vector<TabulatedRow> kept, defects;
  int merged = 0, first_merged_line = 0;
};

Split split_rows(const std::vector<TabulatedRow>& rows) {
  Split s;
  for (const auto& r : rows) {
    if (!r.problem.empty()) {
      s.defects.push_back(r);
      continue;
    }
    if (s.kept.empty() || r.lambda_nm > s.kept.back().lambda_nm) {
      s.kept.push_back(r);
      continue;
    }
    const auto it =
        std::lower_bound(s.kept.begin(), s.kept.end(), r.lambda_nm,
                         [](const TabulatedRow& a, double x) { return a.lambda_nm < x; });
    const bool same_wavelength = it != s.kept.end() && it->lambda_nm == r.lambda_nm;
    if (same_wavelength && it->n == r.n && it->k == r.k) {
      if (s.merged++ == 0) s.first_merged_line = r.line;
      continue;
    }
    TabulatedRow d = r;
    d.misplaced = !same_wavelength;
    d.problem =
        same_wavelength
            ? fmt::format(
                  "wavelengths are not strictly increasing ({} repeats line {} with other values)",
                  nm_text(r.lambda_nm), it->line)
            : fmt::format("wavelengths are not strictly increasing ({} after {} at line {})",
                          nm_text(r.lambda_nm), nm_text(s.kept.back().lambda_nm),
                          s.kept.back().line);
    s.defects.push_back(std::move(d));
  }
  return s;
}

// The used span widened to the rows that interpolation at its ends reads: the nearest row at or
// below its start and at or above its end, valid or not (a defect there is used too).
std::pair<double, double> used_span(const std::vector<TabulatedRow>& rows, const UsedRange& used) {
  double lo = used.min_nm, hi = used.max_nm;
  bool below = false, above = false;
  for (const auto& r : rows) {
    if (r.lambda_nm <= used.min_nm && (!below || r.lambda_nm > lo)) lo = r.lambda_nm, below = true;
    if (r.lambda_nm >= used.max_nm && (!above || r.lambda_nm < hi)) hi = r.lambda_nm, above = true;
  }
  return {lo, hi};
}

}  // namespace

namespace {

// Puts a misplaced row into `kept` (sorted); an exact repeat there is merged, another repeat is an
// error. Returns whether it was inserted.
bool place(std::vector<TabulatedRow>& kept, const TabulatedRow& r, const std::string& file) {
  const auto it = std::lower_bound(kept.begin(), kept.end(), r.lambda_nm,
                                   [](const TabulatedRow& a, double x) { return a.lambda_nm < x; });
  if (it != kept.end() && it->lambda_nm == r.lambda_nm) {
    if (it->n == r.n && it->k == r.k) return false;
    throw InputError(
        file, r.line,
        fmt::format("wavelengths are not strictly increasing ({} repeats line {} with other "
                    "values)",
                    nm_text(r.lambda_nm), it->line));
  }
  kept.insert(it, r);
  return true;
}

std::string rows_text(size_t n) {
  return n == 1 ? "1 row" : fmt::format("{} rows", n);
}

}  // namespace

DispersionBlock TabulatedRows::finish(const UsedRange& used,
                                      std::vector<std::string>& warnings) const {
  Split s = split_rows(rows_);
  if (s.kept.empty()) {
    if (s.defects.empty()) throw InputError(file_, block_line_, "tabulated block has no rows");
    throw InputError(file_, s.defects.front().line, s.defects.front().problem);
  }
  const auto [lo, hi] = used_span(rows_, used);
  std::vector<const TabulatedRow*> dropped, placed;
  for (const auto& d : s.defects) {
    const bool inside = d.lambda_nm >= lo && d.lambda_nm <= hi;
    if (inside && !d.misplaced) throw InputError(file_, d.line, d.problem);
    if (!inside)
      dropped.push_back(&d);
    else if (place(s.kept, d, file_))
      placed.push_back(&d);
  }
  if (!dropped.empty())
    warnings.push_back(fmt::format("{}:{}: {} outside the used {:g}-{:g} nm dropped (first: {})",
                                   file_, dropped.front()->line, rows_text(dropped.size()),
                                   used.min_nm, used.max_nm, dropped.front()->problem));
  if (!placed.empty())
    warnings.push_back(fmt::format("{}:{}: {} out of order placed in wavelength order (first: {})",
                                   file_, placed.front()->line, rows_text(placed.size()),
                                   placed.front()->problem));
  if (s.merged)
    warnings.push_back(fmt::format("{}:{}: {} exact duplicate row{} merged", file_,
                                   s.first_merged_line, s.merged, s.merged == 1 ? "" : "s"));
  DispersionBlock b;
  b.kind = kind_;
  b.line = block_line_;
  for (const auto& r : s.kept) {
    b.lambda_nm.push_back(r.lambda_nm);
    b.n.push_back(r.n);
    b.k.push_back(r.k);
  }
  b.min_nm = b.lambda_nm.front();
  b.max_nm = b.lambda_nm.back();
  return b;
}

}  // namespace fl::spectral
