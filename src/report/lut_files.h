#pragma once
// `lut dfg | ltc-moments | ltc`: the pre-integrated GGX tables (analysis/lut.h) computed and
// written as EXR textures, CSV tables and C++ headers.
#include <string>

#include "analysis/lut/lut.h"
#include "report/writer.h"

namespace fl::report {

struct LutRequest {
  int size = 64;  // cells per axis
  std::string out;
  int samples = analysis::kLutSamples;
  int threads = 0;  // 0: every hardware thread
};

// Each checks the request first (InputError for a size, sample count, thread count or output type
// out of range), then computes the table.
// DFG: out.exr (R = dfg1, G = dfg2, B = dfg_f82), out.csv or out.h (a C++ header).
Output dfg_lut(const LutRequest& request, const analysis::LutProgress& progress = {});
// LTC moments: out.exr (RGB = n_D, f_D, l_D) or out.csv.
Output moments_lut(const LutRequest& request, const analysis::LutProgress& progress = {});
// LTC fit: out.exr gives FILE_1.exr (the inverse matrix), FILE_2.exr (n_D, f_D, l_D, sphere form
// factor) and FILE.csv; out.csv gives the CSV only.
Output ltc_lut(const LutRequest& request, const analysis::LutProgress& progress = {});

// The C++ header of a DFG table: constexpr float kDfgLut[size * size * 3].
std::string dfg_header(const analysis::DfgTable& table);

}  // namespace fl::report
