#include <cmath>
#include <vector>

#include "spectral/ri_database.h"

namespace fl::spectral {

// refractiveindex.info, "Dispersion formulas" (database doc/), formulas 1-9; λ in µm. Missing
// trailing coefficients are 0, as in the database's own tools.
double evaluate_formula(int formula, const std::vector<double>& coeffs, double wl) {
  double C[18] = {0};
  for (size_t i = 0; i < coeffs.size() && i < 17; ++i) C[i + 1] = coeffs[i];
  const double wl2 = wl * wl;
  switch (formula) {
    case 1: {  // Sellmeier: n² − 1 = C1 + Σ Ci λ² / (λ² − Ci+1²)
      double s = 1 + C[1];
      for (int i = 2; i <= 16; i += 2)
        if (C[i] != 0) s += C[i] / (1 - (C[i + 1] / wl) * (C[i + 1] / wl));
      return std::sqrt(s);
    }
    case 2: {  // Sellmeier-2: n² − 1 = C1 + Σ Ci λ² / (λ² − Ci+1)
      double s = 1 + C[1];
      for (int i = 2; i <= 16; i += 2)
        if (C[i] != 0) s += C[i] / (1 - C[i + 1] / wl2);
      return std::sqrt(s);
    }
    case 3: {  // Polynomial: n² = C1 + Σ Ci λ^Ci+1
      double s = C[1];
      for (int i = 2; i <= 16; i += 2)
        if (C[i] != 0) s += C[i] * std::pow(wl, C[i + 1]);
      return std::sqrt(s);
    }
    case 4: {  // RefractiveIndex.INFO: two Sellmeier-like terms plus a polynomial
      double s = C[1];
      if (C[2] != 0) s += C[2] * std::pow(wl, C[3]) / (wl2 - std::pow(C[4], C[5]));
      if (C[6] != 0) s += C[6] * std::pow(wl, C[7]) / (wl2 - std::pow(C[8], C[9]));
      for (int i = 10; i <= 16; i += 2)
        if (C[i] != 0) s += C[i] * std::pow(wl, C[i + 1]);
      return std::sqrt(s);
    }
    case 5: {  // Cauchy: n = C1 + Σ Ci λ^Ci+1
      double s = C[1];
      for (int i = 2; i <= 16; i += 2)
        if (C[i] != 0) s += C[i] * std::pow(wl, C[i + 1]);
      return s;
    }
    case 6: {  // Gases: n − 1 = C1 + Σ Ci / (Ci+1 − λ⁻²)
      double s = 1 + C[1];
      for (int i = 2; i <= 10; i += 2)
        if (C[i] != 0) s += C[i] / (C[i + 1] - 1.0 / wl2);
      return s;
    }
    case 7: {  // Herzberger; 0.028 µm² is the formula's fixed pole
      const double d = wl2 - 0.028;
      return C[1] + C[2] / d + C[3] / (d * d) + C[4] * wl2 + C[5] * wl2 * wl2 +
             C[6] * wl2 * wl2 * wl2;
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

}  // namespace fl::spectral
