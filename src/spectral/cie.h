#pragma once
// CIE colorimetric data read from Debian's colord-data (CGATS text files).
#include <string>
#include <vector>

#include "spectral/spectrum.h"

namespace fl::spectral {

// A spectral CGATS file: SPECTRAL_START_NM / SPECTRAL_END_NM / SPECTRAL_BANDS and one or more
// data sets (rows).
struct CgatsSpectra {
  std::vector<double> lambda_nm;
  std::vector<std::vector<double>> sets;
};
CgatsSpectra read_cgats_spectra(const std::string& path);

struct Observer {
  Spectrum x_bar, y_bar, z_bar;
};

// CIE 1931 2° colour-matching functions on the grid.
Observer cie1931_2deg(const SpectralGrid& grid, const std::string& colord_dir);

// CIE daylight at a correlated colour temperature (CIE 15:2004 §3.1): chromaticity from the
// CCT, then S0 + M1·S1 + M2·S2 from the daylight basis.
Spectrum daylight_spd(double cct_kelvin, const SpectralGrid& grid, const std::string& colord_dir);

// D50, D55, D60, D65, D75, A, E, or Dnnnn (daylight at nnnn K). D60 is daylight at
// 6000·1.4388/1.4380 K (the nominal CCT rescaled to the current c2 constant); D65, D50, D55, A
// and E use colord's tabulated CIE spectra. Throws InputError for an unknown name.
Spectrum illuminant_spd(const std::string& name, const SpectralGrid& grid,
                        const std::string& colord_dir);

// The colord-data folder: $FRESNEL_LAB_COLORD if set, else the build's default.
std::string default_colord_dir();

}  // namespace fl::spectral
