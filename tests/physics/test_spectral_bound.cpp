// Lanczos estimate of λ_max(M⁻¹K) and λ_max(M⁻¹D) (physics/spectral_bound.hpp) against the
// dense eigenvalues of whole levels, and the scale it gives the level's point bounds.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/dense_spectrum.hpp"
#include "physics/spectral_bound.hpp"

using namespace mrsim;
using namespace mrsim::test_support;

TEST(SpectralBound, LanczosMatchesTheDenseLargestEigenvalueFromAbove) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const LevelModel m =
        build_level_model(jittered_box(5, 3, 3, 0.3, seed), law_with(5e4 * seed, 1e4, 2, 0.5));
    for (bool damping : {false, true}) {
      const double truth = omega_max_squared(m, damping);
      const double est =
          largest_mass_scaled_eigenvalue(m.adj, damping ? m.D : m.K, m.mass, 1e-4, 300);
      EXPECT_GE(est, truth * (1 - 1e-9)) << "seed " << seed << " damping " << damping;
      EXPECT_LE(est, truth * (1 + 1e-3)) << "seed " << seed << " damping " << damping;
    }
  }
}

TEST(SpectralBound, EmptyAndZeroOperatorsGiveZero) {
  const LevelModel m = build_level_model(jittered_box(2, 2, 2, 0.1, 1), law_with(5e4, 1e4));
  EXPECT_TRUE(m.D.empty());
  EXPECT_EQ(largest_mass_scaled_eigenvalue(m.adj, m.D, m.mass), 0.0);
  const std::vector<Mat3> zero(m.K.size(), Mat3::Zero());
  EXPECT_EQ(largest_mass_scaled_eigenvalue(m.adj, zero, m.mass), 0.0);
  EXPECT_EQ(m.damping_spectrum.scale, 1.0);
}

TEST(SpectralBound, ScaleIsTheMarginOverTheStarLoosenessAndNeverLoosens) {
  EXPECT_DOUBLE_EQ(spectral_scale(1.0, 2.4).scale, kSpectralMargin / 2.4);
  EXPECT_EQ(spectral_scale(1.0, 1.1).scale, 1.0);  // a tight star bound is kept as proven
  EXPECT_EQ(spectral_scale(0.0, 0.0).scale, 1.0);
}

TEST(SpectralBound, LevelPointBoundsPeakAtTheMarginTimesTheTrueEigenvalue) {
  // After calibration the largest ω_i² of the level is kSpectralMargin × λ_max (dense), for
  // stiffness and damping alike: the level alone is estimated within the margin, where the star
  // sums alone were 2–2.5 times above it.
  const LevelModel m =
      build_level_model(jittered_box(6, 3, 3, 0.25, 7), law_with(5e4, 1e4, 1, 0.2));
  double k_max = 0, c_max = 0;
  for (const PointInertia& star : m.star) {
    const PointInertia p = calibrated(star, m);
    k_max = std::max(k_max, p.stiffness / p.mass);
    c_max = std::max(c_max, p.damping / p.mass);
  }
  EXPECT_LT(m.stiffness_spectrum.scale, 1.0);
  EXPECT_NEAR(k_max / omega_max_squared(m), kSpectralMargin, 2e-3);
  EXPECT_NEAR(c_max / omega_max_squared(m, true), kSpectralMargin, 2e-3);
  EXPECT_GT(m.stiffness_spectrum.star_max / m.stiffness_spectrum.eigenvalue, 1.5);
}
