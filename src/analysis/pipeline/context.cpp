#include "analysis/pipeline/context.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "color/ciede2000_batch.h"
#include "fresnel/ground_truth.h"
#include "util/errors.h"
#include "util/parallel.h"

namespace fl::analysis {

namespace {

// The white of a set of per-wavelength XYZ weights: their sum, in wavelength order.
color::Xyz sum_xyz(const std::vector<color::Xyz>& weights) {
  color::Xyz w;
  for (const auto& v : weights) {
    w.X += v.X;
    w.Y += v.Y;
    w.Z += v.Z;
  }
  return w;
}

const Settings& validated(const Settings& s) {
  if (s.angles < 3 || s.angles > 100000) throw InputError("--angles must be between 3 and 100000");
  if (!(s.eta_outside > 0.0) || !std::isfinite(s.eta_outside))
    throw InputError("the outside medium's index must be positive");
  if (s.step_nm != 5.0 && s.step_nm != 1.0) throw InputError("--step-nm must be 5 or 1");
  return s;
}

// A config space's white named by --ocio-white: ACES (x = 0.32168, y = 0.33767, the white of the
// D60 illuminant's ACES use), or an illuminant's own white from its spectrum and the observer.
std::optional<color::SpaceWhite> space_white(const Settings& s, const spectral::SpectralGrid& grid,
                                             const spectral::Observer& observer) {
  if (s.ocio_white.empty()) return std::nullopt;
  if (s.ocio_config.empty())
    throw InputError("--ocio-white applies to the spaces of an --ocio-config only");
  const std::string source = "white " + s.ocio_white + " given by --ocio-white";
  if (s.ocio_white == "ACES")
    return color::SpaceWhite{color::xyz_from_xy({0.32168, 0.33767}), "D60", source};
  const color::Xyz w =
      sum_xyz(color::xyz_weights(observer, spectral::illuminant_spd(s.ocio_white, grid)));
  return color::SpaceWhite{{w.X / w.Y, 1.0, w.Z / w.Y}, s.ocio_white, source};
}

}  // namespace

namespace {

color::ViewSettings reflectance_view(const Settings& s) {
  return {s.view.display, s.reflectance_view, 0.0, color::kUntonemappedView, true};
}

}  // namespace

Context::Context(const Settings& s)
    : settings_(validated(s)),
      grid_(spectral::SpectralGrid::visible(s.step_nm)),
      spaces_(s.ocio_config.empty() ? color::SpaceLibrary::builtin()
                                    : color::SpaceLibrary::from_config(s.ocio_config, s.ocio_xyz)),
      display_(spaces_, s.space, s.view),
      reflectance_display_(spaces_, s.space, reflectance_view(s)) {
  // The run's page catalog and catalog index: one per database and catalog folder, shared with
  // the settings' copies.
  if (!settings_.paths.pages || settings_.paths.pages->database() != settings_.paths.database)
    settings_.paths.pages = std::make_shared<const spectral::PageCatalog>(settings_.paths.database);
  if (!settings_.paths.catalog || settings_.paths.catalog->folder != settings_.paths.materials)
    settings_.paths.catalog = std::make_shared<const spectral::CatalogIndex>(
        spectral::read_catalog_index(settings_.paths.materials));
  const auto observer = spectral::cie1931_2deg(grid_);
  space_ = spaces_.space(s.space, space_white(s, grid_, observer));
  if (settings_.illuminant.empty()) settings_.illuminant = space_.reference_illuminant;
  const auto illuminant = spectral::illuminant_spd(settings_.illuminant, grid_);
  const auto xyz_w = color::xyz_weights(observer, illuminant);
  illuminant_white_ = sum_xyz(xyz_w);
  const color::Mat3 m =
      space_.xyz_to_rgb * color::adaptation_matrix(color::adaptation_from_name(s.adaptation),
                                                   illuminant_white_, space_.white);
  rgb_weights_.resize(xyz_w.size());
  luminance_weights_.resize(xyz_w.size());
  for (size_t i = 0; i < xyz_w.size(); ++i) {
    rgb_weights_[i] = m * xyz_w[i];
    luminance_weights_[i] = xyz_w[i].Y;
  }

  const int n = s.angles;
  double wsum = 0;
  for (int i = 0; i < n; ++i) {
    const double deg = 90.0 * i / (n - 1);
    const double c = i == n - 1 ? 0.0 : std::cos(deg * std::numbers::pi / 180.0);
    angles_deg_.push_back(deg);
    cos_thetas_.push_back(c);
    const double w = std::sin(deg * std::numbers::pi / 180.0) * c;
    render_weights_.push_back(w);
    wsum += w;
  }
  for (auto& w : render_weights_) w /= wsum;
}

color::Rgb Context::spectrum_to_rgb(const std::vector<double>& v) const {
  color::Rgb out;
  for (size_t i = 0; i < rgb_weights_.size(); ++i) out = out + v[i] * rgb_weights_[i];
  return out;
}

Coverage coverage_of(const Context& ctx, const spectral::SampledIor& s) {
  Coverage c;
  const auto& w = ctx.luminance_weights();
  c.n = c.k = c.both = 0.0;
  for (size_t i = 0; i < w.size(); ++i) {
    const bool k = !s.has_k_data || s.k_measured[i];
    c.n += s.n_measured[i] ? w[i] : 0.0;
    c.k += s.k_measured[i] ? w[i] : 0.0;
    c.both += s.n_measured[i] && k ? w[i] : 0.0;
    c.extrapolated |= !s.n_measured[i] || !k;
  }
  // Divided by the weights' own sum, so that full coverage is exactly 1.
  double total = 0;
  for (double x : w) total += x;
  c.n /= total;
  c.k /= total;
  c.both /= total;
  if (!s.has_k_data) c.k = std::nan("");
  c.uncovered = s.uncovered;
  return c;
}

LoadedMaterial load_material(const Context& ctx, spectral::Material m) {
  auto sampled = spectral::sample_ior(m.constants, ctx.grid(), m.name);
  LoadedMaterial out{std::move(m), std::move(sampled.ior), {}, coverage_of(ctx, sampled)};
  for (const auto& w : out.material.constants.warnings) out.warnings.push_back(w);
  for (auto& w : sampled.warnings) out.warnings.push_back(std::move(w));
  // Everything downstream reads the sampled `ior`; the measured tables are let go, which is most
  // of a whole-database run's memory.
  std::vector<spectral::DispersionBlock>().swap(out.material.constants.blocks);
  return out;
}

std::vector<LoadedMaterial> load_catalog(const Context& ctx) {
  auto materials = spectral::read_catalog(ctx.settings().paths);
  // Sampled concurrently; the first failure in catalog order is the one reported.
  std::vector<LoadedMaterial> out(materials.size());
  parallel_for_all(materials.size(),
                   [&](size_t i) { out[i] = load_material(ctx, std::move(materials[i])); });
  return out;
}

color::Rgb ground_truth_rgb(const Context& ctx, const spectral::ComplexIorSpectrum& ior,
                            double cos_theta, double eta_outside) {
  return fresnel::spectral_reflectance_rgb(ctx.rgb_weights(), ior, cos_theta, eta_outside);
}

std::vector<color::Rgb> ground_truth_curve(const Context& ctx,
                                           const spectral::ComplexIorSpectrum& ior,
                                           double eta_outside) {
  std::vector<color::Rgb> out(ctx.cos_thetas().size());
  fresnel::spectral_reflectance_rgb(ctx.rgb_weights(), ior, ctx.cos_thetas(), eta_outside,
                                    out.data());
  return out;
}

std::vector<color::Lab> lab_curve(const Context& ctx, const std::vector<color::Rgb>& rgb) {
  std::vector<color::Lab> out;
  out.reserve(rgb.size());
  for (const auto& c : rgb) out.push_back(ctx.rgb_to_lab(c));
  return out;
}

std::vector<double> de2000_per_angle(const Context& ctx, const std::vector<color::Lab>& lab_a,
                                     const std::vector<color::Rgb>& b) {
  const auto lab_b = lab_curve(ctx, b);
  std::vector<double> out(lab_a.size());
  color::ciede2000_batch(lab_a, lab_b, out);
  return out;
}

std::vector<double> de2000_per_angle(const Context& ctx, const std::vector<color::Rgb>& a,
                                     const std::vector<color::Rgb>& b) {
  return de2000_per_angle(ctx, lab_curve(ctx, a), b);
}

CurveError curve_error(const Context& ctx, const std::vector<color::Rgb>& truth,
                       const std::vector<color::Rgb>& approx) {
  return curve_error(ctx, lab_curve(ctx, truth), approx);
}

CurveError curve_error(const Context& ctx, const std::vector<color::Lab>& truth_lab,
                       const std::vector<color::Rgb>& approx) {
  const auto de = de2000_per_angle(ctx, truth_lab, approx);
  CurveError e;
  double ss = 0, wss = 0;
  for (size_t i = 0; i < de.size(); ++i) {
    ss += de[i] * de[i];
    e.mean += de[i];
    e.max = std::max(e.max, de[i]);
    wss += ctx.render_weights()[i] * de[i] * de[i];
  }
  e.rms = std::sqrt(ss / de.size());
  e.mean /= de.size();
  e.rms_weighted = std::sqrt(wss);
  return e;
}

}  // namespace fl::analysis
