#include "analysis/ltc/ltc_reference.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "spectral/text_file.h"
#include "util/errors.h"
#include "util/parallel.h"

namespace fl::analysis {

namespace {

// The numbers of the array declared as `name[...] = {` ... `};`, with the line each starts on.
struct ArrayNumbers {
  std::vector<double> values;
  int first_line = 0;
};
ArrayNumbers read_array(const std::string& path, const std::vector<std::string_view>& lines,
                        std::string_view name) {
  ArrayNumbers a;
  size_t k = 0;
  while (k < lines.size() && lines[k].find(std::string(name) + "[") == std::string_view::npos) ++k;
  if (k == lines.size()) throw InputError(path, 0, fmt::format("no array {}", name));
  a.first_line = static_cast<int>(k) + 1;
  for (++k; k < lines.size(); ++k) {
    const auto line = spectral::trim(lines[k]);
    if (line.starts_with("};")) return a;
    for (auto field : spectral::split_fields(line, "{}, \t")) {
      if (field.ends_with('f')) field.remove_suffix(1);
      double v = 0;
      if (!spectral::parse_finite(field, v))
        throw InputError(path, static_cast<int>(k) + 1,
                         fmt::format("'{}' in {} is not a number", field, name));
      a.values.push_back(v);
    }
  }
  throw InputError(path, a.first_line, fmt::format("array {} is not closed by '}};'", name));
}

int read_size(const std::string& path, const std::vector<std::string_view>& lines) {
  for (size_t k = 0; k < lines.size(); ++k) {
    const auto at = lines[k].find("size = ");
    if (at == std::string_view::npos || lines[k].find("int") == std::string_view::npos) continue;
    double v = 0;
    auto field = spectral::trim(lines[k].substr(at + 7));
    if (field.ends_with(';')) field.remove_suffix(1);
    if (!spectral::parse_finite(field, v) || v < 2 || v > 4096 || v != std::floor(v))
      throw InputError(path, static_cast<int>(k) + 1,
                       "table size is not an integer from 2 to 4096");
    return static_cast<int>(v);
  }
  throw InputError(path, 0, "no 'static const int size = N;'");
}

}  // namespace

LtcReferenceTable read_ltc_code_table(const std::string& path) {
  const std::string text = spectral::read_text_file(path);
  const auto lines = spectral::split_lines(text);
  LtcReferenceTable t;
  t.size = read_size(path, lines);
  const size_t cells = static_cast<size_t>(t.size) * t.size;
  const auto inv = read_array(path, lines, "tabMinv");
  const auto mag = read_array(path, lines, "tabMagnitude");
  if (inv.values.size() != 9 * cells)
    throw InputError(
        path, inv.first_line,
        fmt::format("tabMinv has {} numbers, expected {}", inv.values.size(), 9 * cells));
  if (mag.values.size() != cells)
    throw InputError(
        path, mag.first_line,
        fmt::format("tabMagnitude has {} numbers, expected {}", mag.values.size(), cells));
  t.m_inv.resize(cells);
  t.magnitude.resize(cells);
  for (int tv = 0; tv < t.size; ++tv)
    for (int a = 0; a < t.size; ++a) {
      const size_t src = static_cast<size_t>(a) + static_cast<size_t>(t.size) * tv;
      const size_t dst =
          static_cast<size_t>(a) * t.size + tv;  // LutGrid::index(i_nov = tv, j_roughness = a)
      // glm is column-major: the file lists Minv[col][row], so entry (row r, column c) is 3c + r.
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) t.m_inv[dst].m[3 * r + c] = inv.values[9 * src + 3 * c + r];
      t.magnitude[dst] = mag.values[src];
    }
  return t;
}

namespace {

// A point at which both tables are judged: a cell, or the midpoint between two neighbouring cells
// where a shader's bilinear lookup averages their texture entries.
struct JudgedPoint {
  double nov = 1, alpha = 1, n_d = 1;
  bool last_row = false;
  LtcLobe ours, reference;
  int a = 0, b = 0;  // the cells (a == b for a cell)
};

struct Band {
  const char* name;
  std::function<bool(const JudgedPoint&)> in;
};
std::vector<Band> bands() {
  return {{"all", [](const JudgedPoint&) { return true; }},
          {"alpha < 0.1", [](const JudgedPoint& p) { return p.alpha < 0.1; }},
          {"0.1 <= alpha <= 0.5",
           [](const JudgedPoint& p) { return p.alpha >= 0.1 && p.alpha <= 0.5; }},
          {"alpha > 0.5", [](const JudgedPoint& p) { return p.alpha > 0.5; }},
          {"n.v < 0.25", [](const JudgedPoint& p) { return p.nov < 0.25; }},
          {"last row (theta = 1.57)", [](const JudgedPoint& p) { return p.last_row; }}};
}

// The LTC of a texel: M⁻¹ = [[e0, 0, e2], [0, 1, 0], [e1, 0, e3]] (LtcCell::inv_packed order).
LtcLobe lobe_of_entries(const std::array<double, 4>& e) {
  return ltc_lobe(inverse(LtcMatrix{{e[0], 0, e[2], 0, 1, 0, e[1], 0, e[3]}}));
}

std::vector<LtcBandError> band_errors(const std::vector<JudgedPoint>& points,
                                      const std::vector<double>& ours,
                                      const std::vector<double>& reference) {
  std::vector<LtcBandError> out;
  for (const auto& b : bands()) {
    LtcBandError e{b.name};
    for (size_t k = 0; k < points.size(); ++k) {
      if (!b.in(points[k])) continue;
      ++e.cells;
      e.mean += ours[k];
      e.reference_mean += reference[k];
      e.max = std::max(e.max, ours[k]);
      e.reference_max = std::max(e.reference_max, reference[k]);
    }
    if (e.cells > 0) e.mean /= e.cells, e.reference_mean /= e.cells;
    out.push_back(e);
  }
  return out;
}

void judge(const std::vector<JudgedPoint>& points, int samples, std::vector<double>& ours,
           std::vector<double>& reference) {
  ours.assign(points.size(), 0.0);
  reference.assign(points.size(), 0.0);
  parallel_for(points.size(), [&](size_t k) {
    const auto& p = points[k];
    const auto e = ltc_l3_errors(p.nov, p.alpha, p.n_d, {p.ours, p.reference}, samples);
    ours[k] = e[0].relative();
    reference[k] = e[1].relative();
  });
}

// Every pair of neighbouring cells of an n × n grid, (i, j)–(i + 1, j) (along n·v) and
// (i, j)–(i, j + 1), in row order: fn(i, j, i2, j2, along_nov).
template <class Fn>
void for_each_neighbour_pair(int n, Fn fn) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      for (const bool along_nov : {true, false}) {
        const int i2 = i + (along_nov ? 1 : 0), j2 = j + (along_nov ? 0 : 1);
        if (i2 < n && j2 < n) fn(i, j, i2, j2, along_nov);
      }
}

// The largest difference of each texture entry between neighbouring cells.
void fill_jumps(int n, const std::vector<std::array<double, 4>>& entries, bool reference,
                std::array<LtcEntryJump, 4>& out) {
  for (int e = 0; e < 4; ++e) {
    double best = -1;
    for_each_neighbour_pair(n, [&](int i, int j, int i2, int j2, bool along_nov) {
      const double d = std::abs(entries[static_cast<size_t>(j) * n + i][e] -
                                entries[static_cast<size_t>(j2) * n + i2][e]);
      if (d <= best) return;
      best = d;
      if (reference)
        out[e].reference_max = d, out[e].reference_i_nov = i, out[e].reference_j_roughness = j,
        out[e].reference_along_nov = along_nov;
      else
        out[e].max = d, out[e].i_nov = i, out[e].j_roughness = j, out[e].along_nov = along_nov;
    });
  }
}

std::vector<JudgedPoint> midpoints(const LtcTable& table,
                                   const std::vector<std::array<double, 4>>& entries,
                                   const std::vector<std::array<double, 4>>& reference_entries,
                                   int moment_samples) {
  const auto& g = table.grid;
  const int n = g.size;
  std::vector<JudgedPoint> out;
  for_each_neighbour_pair(n, [&](int i, int j, int i2, int j2, bool) {
    JudgedPoint p;
    p.a = g.index(i, j), p.b = g.index(i2, j2);
    p.nov = ltc_nov_at(0.5 * (i + i2) / (n - 1));
    p.alpha = ltc_alpha_at(0.5 * (j + j2) / (n - 1));
    p.last_row = i2 == n - 1;
    std::array<double, 4> mine, theirs;
    for (int e = 0; e < 4; ++e) {
      mine[e] = 0.5 * (entries[p.a][e] + entries[p.b][e]);
      theirs[e] = 0.5 * (reference_entries[p.a][e] + reference_entries[p.b][e]);
    }
    p.ours = lobe_of_entries(mine);
    p.reference = lobe_of_entries(theirs);
    out.push_back(p);
  });
  parallel_for(out.size(), [&](size_t k) {
    out[k].n_d = integrate_moments(out[k].nov, out[k].alpha, moment_samples)[fresnel::Term::One];
  });
  return out;
}

}  // namespace

LtcComparison compare_ltc_tables(const LtcTable& table, const LtcReferenceTable& reference,
                                 int heldout_samples, int moment_samples) {
  const auto& g = table.grid;
  const int n = g.size;
  if (reference.size != n)
    throw InputError(
        fmt::format("reference table is {0}x{0}, the fitted table {1}x{1}", reference.size, n));
  LtcComparison c;
  c.heldout_samples = heldout_samples;
  const size_t count = static_cast<size_t>(n) * n;
  std::vector<std::array<double, 4>> entries(count), reference_entries(count);
  std::vector<JudgedPoint> cells(count);
  for (size_t k = 0; k < count; ++k) {
    const int i = static_cast<int>(k % n), j = static_cast<int>(k / n);
    entries[k] = table.cells[k].inv_packed;
    reference_entries[k] = ltc_texture_entries(reference.m_inv[k]);
    cells[k] = {g.nov[i],
                g.alpha[j],
                table.moments[k][fresnel::Term::One],
                i == n - 1,
                ltc_lobe(table.cells[k].m),
                ltc_lobe(inverse(reference.m_inv[k])),
                static_cast<int>(k),
                static_cast<int>(k)};
  }
  judge(cells, heldout_samples, c.error, c.reference_error);
  c.bands = band_errors(cells, c.error, c.reference_error);
  const auto mids = midpoints(table, entries, reference_entries, moment_samples);
  judge(mids, heldout_samples, c.midpoint_error, c.midpoint_reference_error);
  c.midpoint_bands = band_errors(mids, c.midpoint_error, c.midpoint_reference_error);
  for (size_t k = 0; k < mids.size(); ++k) {
    const auto& p = mids[k];
    c.midpoint_cells.emplace_back(p.a, p.b);
    c.midpoint_excess =
        std::max(c.midpoint_excess, c.midpoint_error[k] - std::max(c.error[p.a], c.error[p.b]));
    c.midpoint_reference_excess = std::max(
        c.midpoint_reference_excess,
        c.midpoint_reference_error[k] - std::max(c.reference_error[p.a], c.reference_error[p.b]));
  }
  c.jumps = ltc_entry_jumps(table, reference);
  return c;
}

std::array<LtcEntryJump, 4> ltc_entry_jumps(const LtcTable& table,
                                            const LtcReferenceTable& reference) {
  const int n = table.grid.size;
  if (reference.size != n)
    throw InputError(
        fmt::format("reference table is {0}x{0}, the fitted table {1}x{1}", reference.size, n));
  const size_t count = static_cast<size_t>(n) * n;
  std::vector<std::array<double, 4>> entries(count), reference_entries(count);
  for (size_t k = 0; k < count; ++k) {
    entries[k] = table.cells[k].inv_packed;
    reference_entries[k] = ltc_texture_entries(reference.m_inv[k]);
  }
  std::array<LtcEntryJump, 4> jumps;
  const char* names[4] = {"inv_m00", "inv_m20", "inv_m02", "inv_m22"};
  for (int e = 0; e < 4; ++e) jumps[e].entry = names[e];
  fill_jumps(n, entries, false, jumps);
  fill_jumps(n, reference_entries, true, jumps);
  return jumps;
}

}  // namespace fl::analysis
