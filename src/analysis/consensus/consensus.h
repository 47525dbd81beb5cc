#pragma once
// Consensus presets: per element (or any named group of pages) the per-wavelength median of the
// bulk measurements' reflectance at 0° and at arccos(1/7), turned back into n, k; every page's
// ΔE2000 distance from it, outliers, the recommended page and the uncertainty (docs/consensus.md).
#include <complex>
#include <functional>
#include <string>
#include <vector>

#include "analysis/consensus/spread.h"
#include "analysis/pipeline/context.h"
#include "analysis/study/study.h"
#include "util/table.h"

namespace fl::analysis {

// μ̄ = 1/7 (θ ≈ 81.79°), the second angle of the consensus: where F82 and OpenPBR's edge tint are
// read.
inline constexpr double kConsensusCosGrazing = 1.0 / 7.0;

// Kernel: the relative index η + iκ whose unpolarized Fresnel reflectance is r0 at normal
// incidence and r82 at cos θ = 1/7 (Born & Wolf §14.2). Normal incidence fixes a circle in the
// (η, κ) plane, κ² = ((η + 1)² r0 − (η − 1)²)/(1 − r0) for η between (1 − √r0)/(1 + √r0) and its
// inverse (Gulbrandsen 2014's parameterization); along it the root of R(1/7) − r82 nearest
// `eta_hint` (in log η) is found by a log-spaced scan and bisection. When no point of the circle
// reaches r82, the nearest reflectance is taken. Requires 0 < r0 < 1.
std::complex<double> invert_reflectance_pair(double r0, double r82, double eta_hint);

// The consensus spectrum of `pages` (same grid): at each wavelength the median over the pages of
// R(0°) and of R(cos θ = 1/7) for the index relative to eta_outside, inverted back
// (invert_reflectance_pair, hinted by the median η) and scaled by eta_outside again. So the
// consensus reproduces both medians exactly; the median of identical pages is that page.
spectral::ComplexIorSpectrum consensus_ior(
    const std::vector<const spectral::ComplexIorSpectrum*>& pages, double eta_outside);

// Outliers: a page farther from the consensus than the bulk pages' median distance plus
// kOutlierMads robust standard deviations (1.4826 × the median absolute deviation), and farther
// than kOutlierMinDe00 (a difference one sees side by side), in F0 or in F82.
inline constexpr double kOutlierMads = 3.0;
inline constexpr double kMadToSigma = 1.4826;  // MAD of a normal distribution × this = σ
inline constexpr double kOutlierMinDe00 = 2.0;
// Recommended page: the bulk page nearest the consensus (the larger of its F0 and F82 distances);
// pages within kRecommendTieDe00 of the nearest count as tied, and the newest of them is taken.
inline constexpr double kRecommendTieDe00 = 0.05;

// A user group: NAME=GLOB[,GLOB...], a page glob (named by itself), or an element: a book of the
// main shelf by symbol or by the name the catalog gives it ("Au", "gold", "aluminium").
struct ConsensusRequest {
  std::string name;
  std::vector<std::string> globs;
};
// InputError for an element the catalog does not know.
ConsensusRequest consensus_request(const spectral::DataPaths& paths, const std::string& spec);
// The common name of a book of the database's catalog: "Au (Gold)" → "gold" (empty: none).
std::string common_name(const std::string& book_name);

struct PageDistance {
  const MaterialStudy* page = nullptr;
  double f0_de00 = 0, f82_de00 = 0;
  bool used = false;  // a bulk measurement: part of the consensus
  bool outlier = false;
  std::string reason;  // why it is an outlier (empty otherwise)
};

struct ConsensusGroup {
  std::string name;                 // "main/Au", or the user's name
  std::string book_name;            // "Au (Gold)" (the first page's)
  std::vector<PageDistance> pages;  // every page of the group, in the pages' order
  int used = 0;                     // bulk pages in the consensus
  double f0_median = 0, f0_max = 0, f82_median = 0, f82_max = 0;  // over the used pages
  color::Rgb f0_lo, f0_hi, f82_lo, f82_hi, g_lo, g_hi;            // ranges over the used pages
  double f0_limit = 0, f82_limit = 0;                             // the outlier limits (ΔE2000)
  std::string recommended, recommended_reason;
  double recommended_de00 = 0;  // the larger of its F0 and F82 distances
  int outliers = 0;
};

// Consensus materials (their studies point into `materials`: keep the set whole, move it whole).
struct ConsensusSet {
  std::vector<LoadedMaterial> materials;
  std::vector<MaterialStudy> studies;  // studies[i] of materials[i]
  std::vector<ConsensusGroup> groups;  // groups[i] of materials[i]
};

struct GroupPages {
  std::string name;
  std::vector<const MaterialStudy*> pages;  // studied pages (derived F0, F82 and g are read)
};
// The library's groups: spread_group of every metal page covering kSpreadMinCoverage.
std::vector<GroupPages> page_groups(const std::vector<MaterialStudy>& pages);

// A consensus for every group with at least one bulk page, studied under `options`.
ConsensusSet build_consensus(const Context& ctx, const std::vector<GroupPages>& groups,
                             const StudyOptions& options,
                             const std::function<void(int, int)>& progress = {});

// The group of a page's consensus and the page's distance (nullptr: none).
const PageDistance* find_distance(const ConsensusSet& set, const MaterialStudy& page);

// Appends to a presets table of set.studies (one row per consensus, same order) the uncertainty:
// pages used, F0 and F82 ΔE2000 median and max, each F0, F82, g channel's range, the recommended
// page and its distance, the outliers.
void add_uncertainty_columns(Table& t, const ConsensusSet& set);

// The consensus of each request (one group per request, named by it) over the metal pages its
// globs match that cover kSpreadMinCoverage. InputError for a request without such a page or
// without a bulk measurement among them.
struct RequestedConsensus {
  PageStudies pages;
  ConsensusSet set;
};
RequestedConsensus consensus_for(const Context& ctx, const std::vector<ConsensusRequest>& requests,
                                 const StudyOptions& options,
                                 const std::function<void(int, int)>& progress = {});

// One row per group: pages used, consensus F0/F82, uncertainty, outliers with reasons, the
// recommended page.
Table consensus_table(const Context& ctx, const ConsensusSet& set);
// One row per page: kind, distance from its group's consensus, outlier and why.
Table consensus_pages_table(const ConsensusSet& set);
// Pages and outliers per page kind.
Table outlier_kinds_table(const ConsensusSet& set);

// physicallybased.info's metals (PEER_DIR/physicallybased.csv, physicallybased_pages.csv,
// openpbr_examples.csv): each published preset's page, its distance from its element's consensus,
// and the published F0 and F82 (acescg) against the spread of the bulk pages. Reads pages and
// computes consensus itself. InputError for a missing or malformed file.
Table peer_table(const Context& ctx, const std::string& peer_dir,
                 const std::function<void(int, int)>& progress = {});

}  // namespace fl::analysis
