#pragma once
// The files of `basis`: the data-driven Fresnel basis as tables and as a C++ header.
#include <string>

#include "analysis/basis/basis.h"
#include "io/writer.h"

namespace fl::jobs {

// Paths relative to the output folder: basis_functions.csv (the terms sampled),
// basis_polynomials.csv (coefficients, fit errors), basis_energy.csv (singular values),
// basis_projection.csv (error per K over the pages), basis_pages.csv (per page), basis.md (the
// tables with their readings, and the pages left out by reason) and
// basis_polynomials.h (the polynomials as constexpr data, src/fresnel/basis_polynomials.h).
// `command` is the command line, for basis.md and the header.
io::Files basis_files(const analysis::Context& ctx, const analysis::FresnelBasis& basis,
                      const std::string& command);

// The generated header alone.
std::string basis_header(const analysis::FresnelBasis& basis, const std::string& command);

}  // namespace fl::jobs
