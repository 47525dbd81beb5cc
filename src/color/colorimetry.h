#pragma once
// Spectrum → XYZ and chromatic adaptation.
#include <string>
#include <vector>

#include "color/matrix.h"
#include "spectral/cie.h"

namespace fl::color {

enum class Adaptation { Bradford, Cat02, None };
Adaptation adaptation_from_name(const std::string& name);  // bradford | cat02 | none
const char* to_string(Adaptation a);

// Von Kries adaptation in the method's cone space, mapping src_white to dst_white (Lam 1985 for
// Bradford, CIECAM02 for CAT02; None is the identity).
Mat3 adaptation_matrix(Adaptation method, const Xyz& src_white, const Xyz& dst_white);

// Per-wavelength weights w(λ) with XYZ = Σ R(λ)·w(λ), the same normalization as above.
std::vector<Xyz> xyz_weights(const spectral::Observer& obs, const spectral::Spectrum& illuminant);

}  // namespace fl::color
