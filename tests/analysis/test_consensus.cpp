// Consensus presets (analysis/consensus): the inversion of a reflectance pair against an
// independent complex-amplitude Fresnel implementation, the per-wavelength median's identities
// (identical pages give that page; one outlier page does not move it), and outlier flags, distances
// and the recommended page over pages built here.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "analysis/consensus/consensus.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl::analysis {
namespace {

// Round trips of the inversion: bisection to 1e-15 relative in η; κ follows from the circle.
constexpr double kInversionTolerance = 1e-9;
// A consensus spectrum's reflectances against the independent formula (both in double).
constexpr double kReflectanceTolerance = 1e-10;

// Born & Wolf §13.4 by complex amplitudes (an implementation independent of fresnel/exact.h's
// a/b form): cos θ_t = sqrt(1 − sin²θ/ñ²), r_s = (cos θ − ñ cos θ_t)/(cos θ + ñ cos θ_t),
// r_p = (ñ cos θ − cos θ_t)/(ñ cos θ + cos θ_t), R = (|r_s|² + |r_p|²)/2.
double amplitude_reflectance(double cos_theta, std::complex<double> n) {
  const double sin2 = 1.0 - cos_theta * cos_theta;
  const std::complex<double> cos_t = std::sqrt(1.0 - sin2 / (n * n));
  const auto rs = (cos_theta - n * cos_t) / (cos_theta + n * cos_t);
  const auto rp = (n * cos_theta - cos_t) / (n * cos_theta + cos_t);
  return 0.5 * (std::norm(rs) + std::norm(rp));
}

// Indices of metals at 550 nm (Johnson & Christy; Rakić for Al), and two edge cases: a large
// reflectance with η ≪ 1 and a weak absorber.
const std::vector<std::complex<double>> kIndices{{0.43, 2.45}, {0.059, 3.59}, {0.96, 2.58},
                                                 {0.96, 6.69}, {2.87, 3.36},  {1.5, 0.6}};

TEST(ConsensusInversion, RecoversTheIndexFromItsTwoReflectances) {
  for (const auto n : kIndices) {
    const double r0 = amplitude_reflectance(1.0, n);
    const double r82 = amplitude_reflectance(kConsensusCosGrazing, n);
    const auto back = invert_reflectance_pair(r0, r82, n.real());
    EXPECT_NEAR(back.real(), n.real(), kInversionTolerance * (1 + n.real())) << n;
    EXPECT_NEAR(back.imag(), n.imag(), kInversionTolerance * (1 + n.imag())) << n;
  }
}

spectral::ComplexIorSpectrum spectrum(std::complex<double> at_start, std::complex<double> slope) {
  spectral::ComplexIorSpectrum s;
  s.grid = spectral::SpectralGrid{};
  s.ior.resize(s.grid.count);
  for (int i = 0; i < s.grid.count; ++i) s.ior[i] = at_start + slope * (i / double(s.grid.count));
  return s;
}

TEST(ConsensusSpectrum, IdenticalPagesGiveThatPage) {
  const auto page = spectrum({0.4, 2.2}, {-0.2, 1.5});
  const auto c = consensus_ior({&page, &page, &page}, 1.0);
  ASSERT_EQ(c.ior.size(), page.ior.size());
  for (size_t i = 0; i < c.ior.size(); ++i) {
    EXPECT_NEAR(c.ior[i].real(), page.ior[i].real(), kInversionTolerance * 4) << i;
    EXPECT_NEAR(c.ior[i].imag(), page.ior[i].imag(), kInversionTolerance * 4) << i;
  }
}

TEST(ConsensusSpectrum, OneOutlierPageDoesNotMoveIt) {
  const auto page = spectrum({0.4, 2.2}, {-0.2, 1.5});
  const auto outlier = spectrum({2.9, 3.0}, {0.5, 0.5});  // iron-like against gold-like
  const auto c = consensus_ior({&page, &outlier, &page, &page}, 1.0);
  for (size_t i = 0; i < c.ior.size(); ++i) {
    EXPECT_NEAR(c.ior[i].real(), page.ior[i].real(), kInversionTolerance * 4) << i;
    EXPECT_NEAR(c.ior[i].imag(), page.ior[i].imag(), kInversionTolerance * 4) << i;
  }
}

TEST(ConsensusSpectrum, ReproducesTheMediansOfBothReflectances) {
  const std::vector<spectral::ComplexIorSpectrum> pages{
      spectrum({0.4, 2.2}, {-0.2, 1.5}), spectrum({0.3, 2.4}, {-0.1, 1.2}),
      spectrum({0.6, 2.0}, {-0.3, 1.8}), spectrum({0.5, 2.5}, {0.0, 1.0}),
      spectrum({0.2, 2.1}, {0.1, 1.6})};
  std::vector<const spectral::ComplexIorSpectrum*> ptrs;
  for (const auto& p : pages) ptrs.push_back(&p);
  const double eta_outside = 1.33;  // under water: the medians are of the relative index's R
  const auto c = consensus_ior(ptrs, eta_outside);
  for (size_t i = 0; i < c.ior.size(); i += 7)
    for (const double mu : {1.0, kConsensusCosGrazing}) {
      std::vector<double> r;
      for (const auto& p : pages) r.push_back(amplitude_reflectance(mu, p.ior[i] / eta_outside));
      std::sort(r.begin(), r.end());
      EXPECT_NEAR(amplitude_reflectance(mu, c.ior[i] / eta_outside), r[2], kReflectanceTolerance)
          << i << " " << mu;
    }
}

// Pages built here: four gold-like measurements close together, one far (bulk, so in the median
// but outvoted), and a computed page farther still (not in the median).
class ConsensusGroupTest : public ::testing::Test {
 protected:
  void SetUp() override {
    add("P1", {0.40, 2.20}, 1972);
    add("P2", {0.42, 2.22}, 2015);
    add("P3", {0.41, 2.18}, 2009);
    add("P4", {0.43, 2.21}, 2012);
    add("Far", {1.40, 1.90}, 1990);
    add("DFT", {0.20, 3.00}, 2009, spectral::PageKind::Computed);
    StudyOptions o;
    o.fit = false;
    studies_ = study_materials(ctx_, materials_, o);
    set_ = build_consensus(ctx_, page_groups(studies_), o);
  }
  void add(const std::string& name, std::complex<double> n, int year,
           spectral::PageKind kind = spectral::PageKind::Bulk) {
    LoadedMaterial m;
    m.material.origin = spectral::Material::Origin::Page;
    m.material.source = m.material.name = m.material.key = "main/Au/nk/" + name;
    m.material.material_class = spectral::MaterialClass::Metal;
    m.material.page_class = {kind, "", year};
    m.material.bulk_measurement = kind == spectral::PageKind::Bulk;
    m.ior = spectrum(n, {-0.1, 1.0});
    materials_.push_back(std::move(m));
  }
  const PageDistance& page(const std::string& name) const {
    for (const auto& p : set_.groups.at(0).pages)
      if (p.page->material->material.source == "main/Au/nk/" + name) return p;
    throw std::runtime_error("no page " + name);
  }
  Context ctx_{Settings{}};
  std::vector<LoadedMaterial> materials_;
  std::vector<MaterialStudy> studies_;
  ConsensusSet set_;
};

TEST_F(ConsensusGroupTest, FlagsTheFarPagesAndRecommendsTheNearest) {
  ASSERT_EQ(set_.groups.size(), 1u);
  const auto& g = set_.groups[0];
  EXPECT_EQ(g.name, "main/Au");
  EXPECT_EQ(g.used, 5);
  EXPECT_FALSE(page("DFT").used);
  EXPECT_TRUE(page("Far").outlier);
  EXPECT_TRUE(page("DFT").outlier);
  EXPECT_NE(page("DFT").reason.find("computed"), std::string::npos);
  for (const char* near : {"P1", "P2", "P3", "P4"}) EXPECT_FALSE(page(near).outlier) << near;
  EXPECT_EQ(g.outliers, 2);
  // The limits: at least kOutlierMinDe00, and the far page beyond.
  EXPECT_GE(g.f0_limit, kOutlierMinDe00);
  EXPECT_GT(page("Far").f0_de00, g.f0_limit);
  // The recommended page is the one nearest (max of F0 and F82 distance), or a newer one within
  // the tie margin.
  double nearest = INFINITY;
  for (const char* p : {"P1", "P2", "P3", "P4"})
    nearest = std::min(nearest, std::max(page(p).f0_de00, page(p).f82_de00));
  EXPECT_LE(g.recommended_de00, nearest + kRecommendTieDe00);
  EXPECT_NE(g.recommended, "main/Au/nk/Far");
  EXPECT_NE(g.recommended, "main/Au/nk/DFT");
  // Uncertainty: the largest distance of a used page, and F0 ranges enclosing every used page's.
  EXPECT_NEAR(g.f0_max, page("Far").f0_de00, 1e-12);
  for (const auto& p : g.pages)
    if (p.used)
      for (int c = 0; c < 3; ++c) {
        EXPECT_LE(g.f0_lo[c], p.page->derived.f0[c]);
        EXPECT_GE(g.f0_hi[c], p.page->derived.f0[c]);
      }
}

TEST_F(ConsensusGroupTest, TablesCountOutliersPerKind) {
  const auto kinds = outlier_kinds_table(set_);
  ASSERT_EQ(kinds.rows.size(), 3u);  // bulk, computed, all
  EXPECT_EQ(std::get<std::string>(kinds.rows[0][0]), "bulk");
  EXPECT_EQ(std::get<long long>(kinds.rows[0][1]), 5);
  EXPECT_EQ(std::get<long long>(kinds.rows[0][2]), 1);
  EXPECT_EQ(std::get<std::string>(kinds.rows[1][0]), "computed");
  EXPECT_EQ(std::get<long long>(kinds.rows[1][2]), 1);
  EXPECT_EQ(std::get<long long>(kinds.rows[2][2]), 2);
}

TEST(ConsensusRequests, ElementsGlobsAndNamedGroups) {
  test::TempDir db;
  db.file("catalog-nk.yml",
          "- SHELF: main\n"
          "  content:\n"
          "    - BOOK: Al\n"
          "      name: \"Al (Aluminium)\"\n"
          "      content:\n"
          "        - PAGE: Rakic\n"
          "          data: main/Al/nk/Rakic.yml\n");
  const spectral::DataPaths paths{db.path(), ""};
  EXPECT_EQ(consensus_request(paths, "Al").globs, std::vector<std::string>{"main/Al/**"});
  EXPECT_EQ(consensus_request(paths, "aluminium").name, "main/Al");
  EXPECT_EQ(consensus_request(paths, "main/Au/nk/*").globs,
            std::vector<std::string>{"main/Au/nk/*"});
  const auto named = consensus_request(paths, "noble=main/Au/**,main/Ag/**");
  EXPECT_EQ(named.name, "noble");
  EXPECT_EQ(named.globs, (std::vector<std::string>{"main/Au/**", "main/Ag/**"}));
  EXPECT_THROW(consensus_request(paths, "Unobtainium"), InputError);
  EXPECT_THROW(consensus_request(paths, "=main/**"), InputError);
}

}  // namespace
}  // namespace fl::analysis
