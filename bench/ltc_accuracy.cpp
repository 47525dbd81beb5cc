// The 64 × 64 LTC fit (`lut ltc`) against ltc_code's published table (Heitz, Dupuy, Hill & Neubelt
// 2016; fit/results/ltc.inc of Heitz & Hill's ltc_code), cell by cell on held-out error
// (analysis/ltc/ltc_reference.h), and the fit's wall and CPU time (medians of --runs runs, default
// 5). Writes Markdown; scripts/ltc_accuracy.sh writes reports/ltc-vs-ltc_code.md with it.
//   ltc_accuracy [--out FILE] [--runs N] [--reference ltc.inc]
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "analysis/ltc/ltc_comparison.h"
#include "analysis/ltc/ltc_reference.h"
#include "analysis/lut/lut.h"
#include "documents/table_formats.h"
#include "io/writer.h"
#include "util/quantile.h"

namespace {

using fl::analysis::LtcComparison;
using fl::analysis::LtcReferenceTable;
using fl::analysis::LtcTable;

// Fresh directions per strategy for each cell's and midpoint's held-out error.
constexpr int kHeldOutSamples = 4096;
// The roughness columns of the grazing-row table: α from 0.06 to 0.40.
constexpr int kFirstColumn = 16, kLastColumn = 40;

struct Timing {
  std::vector<double> seconds, cpu_seconds;
  LtcTable table;
};

// The fit as `lut ltc --size 64` runs it (every hardware thread), `runs` times: wall time, and the
// process's CPU time over all threads (std::clock), which load from other work inflates less.
Timing time_fits(int runs) {
  Timing t;
  for (int r = 0; r < runs; ++r) {
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    t.table = fl::analysis::fit_ltc_table(64);
    t.cpu_seconds.push_back(static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC);
    t.seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return t;
}

std::string grazing_row(const LtcTable& t, const LtcReferenceTable& ref, const LtcComparison& c) {
  const auto& g = t.grid;
  const int i = g.size - 1;
  std::string s =
      "| roughness column | alpha | held-out error | ltc_code | inv_m02 | ltc_code inv_m02 |\n"
      "|---|---|---|---|---|---|\n";
  for (int j = kFirstColumn; j <= kLastColumn; ++j) {
    const int k = g.index(i, j);
    const auto theirs = fl::analysis::ltc_texture_entries(ref.m_inv[k]);
    s += fmt::format("| {} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} |\n", j, g.alpha[j],
                     c.error[k], c.reference_error[k], t.cells[k].inv_packed[2], theirs[2]);
  }
  return s;
}

std::string timing_section(const Timing& t) {
  std::string runs, cpu;
  for (double s : t.seconds) runs += fmt::format("{}{:.2f}", runs.empty() ? "" : ", ", s);
  for (double s : t.cpu_seconds) cpu += fmt::format("{}{:.2f}", cpu.empty() ? "" : ", ", s);
  double load[3] = {0, 0, 0};
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3) load[0] = -1;
    std::fclose(f);
  }
  return fmt::format(
      "## 64 × 64 fit time\n\n`fit_ltc_table(64)` as `lut ltc --size 64` runs it (moments with {} "
      "samples per cell, then the fits; every hardware thread): **{:.2f} s** wall time, the "
      "median of {} runs ({} s; minimum {:.2f} s), on {} hardware threads; CPU time over all "
      "threads {:.2f} s, the median ({} s). Load average {:.1f} at the end (other work shares the "
      "machine).\n",
      fl::analysis::kLutSamples, fl::median(t.seconds), t.seconds.size(), runs,
      *std::min_element(t.seconds.begin(), t.seconds.end()), std::thread::hardware_concurrency(),
      fl::median(t.cpu_seconds), cpu, load[0]);
}

std::string report(const Timing& timing, const LtcReferenceTable& ref, const LtcComparison& c) {
  const auto tables = fl::analysis::ltc_comparison_tables(c);
  std::string s = fmt::format(
      "# LTC fit against ltc_code's published table\n\n"
      "Written by `scripts/ltc_accuracy.sh` (`bench/ltc_accuracy`), not by `reproduce`: the fit "
      "and "
      "the evaluation take seconds, and the timing depends on the machine.\n\n"
      "- Tables: `fresnel-lab lut ltc --size 64` (this tool) and ltc_code's `fit/results/ltc.inc` "
      "(Heitz, Dupuy, Hill & Neubelt 2016), the same 64 × 64 cells (view x = sqrt(1 - cos θ), θ "
      "capped at 1.57; roughness r, α = max(r², 1e-5)).\n"
      "- Error: Heitz's L3 error relative to the lobe, (∫ |ρ cos − n_D D_LTC|³ dω / ∫ (ρ cos)³ "
      "dω)^(1/3), estimated per cell with {0} GGX visible-normal directions and {0} directions "
      "drawn from the LTC under test (balance heuristic), from a Hammersley set that neither fit "
      "used. Both tables' LTCs are scaled by this tool's n_D (the magnitude is not part of either "
      "fit).\n"
      "- Midpoints: half-way between neighbouring cells in texture coordinates, the LTC a bilinear "
      "lookup gives (the mean of the two cells' texture entries) against the lobe there.\n\n",
      c.heldout_samples);
  for (const auto& t : tables) s += fl::documents::to_markdown(t, 2) + "\n";
  s += fmt::format("## Grazing row (θ = 1.57), roughness columns {} to {}\n\n", kFirstColumn,
                   kLastColumn);
  s += grazing_row(timing.table, ref, c) + "\n";
  s += timing_section(timing);
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out, reference = FL_LTC_CODE_TABLE;
  int runs = 5;
  for (int k = 1; k + 1 < argc; k += 2) {
    const std::string flag = argv[k];
    if (flag == "--out")
      out = argv[k + 1];
    else if (flag == "--runs")
      runs = std::max(1, std::atoi(argv[k + 1]));
    else if (flag == "--reference")
      reference = argv[k + 1];
  }
  try {
    const auto ref = fl::analysis::read_ltc_code_table(reference);
    const Timing timing = time_fits(runs);
    const auto c = fl::analysis::compare_ltc_tables(timing.table, ref, kHeldOutSamples);
    const std::string md = report(timing, ref, c);
    if (out.empty())
      std::fputs(md.c_str(), stdout);
    else
      fl::io::write_file_atomic(out, md);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ltc_accuracy: %s\n", e.what());
    return 2;
  }
  return 0;
}
