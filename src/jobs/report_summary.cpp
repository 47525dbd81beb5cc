#include "jobs/report_summary.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace fl::jobs {
namespace {

const Table* find_table(const std::vector<Table>& tables, const std::string& name) {
  for (const auto& t : tables)
    if (t.name == name) return &t;
  return nullptr;
}

double number(const Cell& c) {
  if (const auto* d = std::get_if<double>(&c)) return *d;
  if (const auto* n = std::get_if<long long>(&c)) return static_cast<double>(*n);
  return std::numeric_limits<double>::quiet_NaN();
}

std::string text(const Cell& c) {
  if (const auto* s = std::get_if<std::string>(&c)) return *s;
  return fmt::format("{:g}", number(c));
}

// Per class, the model and parameters with the lowest mean IBL RMS ΔE2000 over the class's
// materials.
std::string best_rendered(const Table& t) {
  const int cls = column_index(t, "class"), model = column_index(t, "model");
  const int params = column_index(t, "parameters");
  const int err = column_index(t, "ibl_rms_de00");
  std::map<std::string, std::map<std::string, std::pair<double, int>>> sums;  // class → model
  for (const auto& row : t.rows) {
    const double e = number(row[err]);
    if (!std::isfinite(e)) continue;
    auto& s = sums[text(row[cls])][text(row[model]) + " (" + text(row[params]) + ")"];
    s.first += e;
    ++s.second;
  }
  std::string line;
  for (const auto& [c, models] : sums) {
    const auto best = std::min_element(models.begin(), models.end(), [](auto& a, auto& b) {
      return a.second.first / a.second.second < b.second.first / b.second.second;
    });
    line += fmt::format("{}{}: {} {:.3f}", line.empty() ? "" : "; ", c, best->first,
                        best->second.first / best->second.second);
  }
  return "**Best model per class as rendered** (lut-accuracy: mean image-based-lighting RMS "
         "ΔE2000 over the class's materials): " +
         line + ".";
}

// The talk's Schlick values: how many are reproduced, and the misses with both values.
std::string talk_schlick(const Table& t) {
  const int name = column_index(t, "material"), ours = column_index(t, "ours");
  const int talk = column_index(t, "talk"), miss = column_index(t, "misses");
  std::string misses;
  int n = 0, missed = 0;
  for (const auto& row : t.rows) {
    ++n;
    if (text(row[miss]) != "yes") continue;
    ++missed;
    misses += fmt::format("{}{} (ours {:.3f}, the talk's {:.3f})", misses.empty() ? "" : ", ",
                          text(row[name]), number(row[ours]), number(row[talk]));
  }
  return fmt::format(
      "**The talk's Schlick table** (talk_spread): {} of {} metals reproduced within its "
      "tolerance{}.",
      n - missed, n, missed ? "; differs for " + misses : "");
}

// The talk's method table: its columns ranked by their mean over the metals.
std::string talk_methods(const Table& t) {
  std::vector<std::pair<double, std::string>> means;
  for (size_t c = 1; c < t.columns.size(); ++c) {
    if (t.columns[c].name.rfind("coverage", 0) == 0) continue;
    double sum = 0;
    int n = 0;
    for (const auto& row : t.rows)
      if (const double v = number(row[c]); std::isfinite(v)) sum += v, ++n;
    if (n > 0) means.emplace_back(sum / n, t.columns[c].name);
  }
  std::sort(means.begin(), means.end());
  std::string line;
  for (const auto& [mean, col] : means)
    line += fmt::format("{}`{}` {:.3f}", line.empty() ? "" : " < ", col, mean);
  return "**The talk's method table** (methods, mean RMS ΔE2000 over the metals, best first): " +
         line + ".";
}

// The Pareto front of one cost column: the models no other model beats on both cost and error.
std::string pareto(const Table& t, const std::string& flag, const std::string& cost,
                   const std::string& unit, const std::string& label) {
  const int model = column_index(t, "model"), params = column_index(t, "parameters");
  const int f = column_index(t, flag), c = column_index(t, cost);
  const int err = column_index(t, "median_rms_de00");
  std::vector<std::pair<double, std::string>> front;
  for (const auto& row : t.rows)
    if (text(row[f]) == "yes")
      front.emplace_back(number(row[c]),
                         fmt::format("{} ({}) {:.3g} {} → {:.3f}", text(row[model]),
                                     text(row[params]), number(row[c]), unit, number(row[err])));
  std::sort(front.begin(), front.end());
  std::string line;
  for (const auto& [cost_value, entry] : front) line += (line.empty() ? "" : ", ") + entry;
  return "**Speed/error front, " + label + "** (speed: cost → median RMS ΔE2000): " + line + ".";
}

}  // namespace

std::vector<std::string> report_summary(const std::vector<Table>& tables) {
  std::vector<std::string> lines;
  if (const auto* t = find_table(tables, "lut-accuracy")) lines.push_back(best_rendered(*t));
  if (const auto* t = find_table(tables, "talk_spread")) lines.push_back(talk_schlick(*t));
  if (const auto* t = find_table(tables, "methods")) lines.push_back(talk_methods(*t));
  if (const auto* t = find_table(tables, "speed")) {
    lines.push_back(pareto(*t, "pareto_cpu", "cpu_ns_per_eval", "ns", "CPU"));
    lines.push_back(pareto(*t, "pareto_gpu", "gpu_instructions", "instructions", "GPU"));
  }
  return lines;
}

}  // namespace fl::jobs
