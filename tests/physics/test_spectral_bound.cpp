// Lanczos estimate of λ_max(M⁻¹K) and λ_max(M⁻¹D) (physics/spectral_bound.hpp) against the
// dense eigenvalues of whole levels, and the scale it gives the level's point bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

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

TEST(SpectralBound, LanczosFindsWhatTheSemiImplicitFilterLeavesExplicit) {
  // λ_max(M⁻¹(K − 2 blockdiag K)): signed, matched from above to 1e-3 of λ_max(M⁻¹K).
  for (unsigned seed : {1u, 2u, 3u}) {
    const LevelModel m =
        build_level_model(jittered_box(5, 3, 3, 0.3, seed), law_with(5e4 * seed, 1e4), true);
    const double truth = omega_max_squared(m, false, true), full = omega_max_squared(m);
    const double est = largest_filtered_eigenvalue(m.adj, m.K, m.mass, 1e-4, 300);
    EXPECT_GE(est, truth - 1e-9 * full) << "seed " << seed;
    EXPECT_LE(est, truth + 1e-3 * full) << "seed " << seed;
    // Positive, and a fraction of λ_max(M⁻¹K), but not always below the thesis' quarter: at
    // λ = 1.5e5, μ = 1e4 (ν = 0.47) it is 0.252 of it, where the doubled step is optimistic.
    EXPECT_GT(truth, 0.0);
    EXPECT_LT(truth, 0.3 * full) << "seed " << seed;
    EXPECT_DOUBLE_EQ(m.filter_spectrum.scale,
                     kSpectralMargin * m.filter_spectrum.eigenvalue /
                         (kSemiImplicitShare * m.stiffness_spectrum.star_max));
  }
  // Measured only for the semi-implicit integrators.
  const LevelModel plain = build_level_model(jittered_box(3, 2, 2, 0.1, 1), law_with(5e4, 1e4));
  EXPECT_EQ(plain.filter_spectrum.scale, 1.0);
}

TEST(SpectralBound, FilterScaleKeepsTheMarginOnEitherSign) {
  // Positive λ_f: the margin above it; negative (no elastic limit): closer to zero, never past.
  EXPECT_DOUBLE_EQ(filter_scale(1.0, 4.0, 8.0, 0.0).scale,
                   kSpectralMargin / (kSemiImplicitShare * 8.0));
  EXPECT_LT(filter_scale(-1.0, 4.0, 8.0, 0.0).scale, 0.0);
  EXPECT_GT(filter_scale(-1.0, 4.0, 8.0, 0.0).scale, -1.0 / (kSemiImplicitShare * 8.0));
  EXPECT_EQ(filter_scale(1.0, 4.0, 0.0, 0.0).scale, 1.0);
  // Green–Lagrange: the tangent's growth counted against λ_K, where it exceeds the margin.
  EXPECT_DOUBLE_EQ(filter_scale(0.1, 4.0, 8.0, kFilterStiffening).scale,
                   (0.1 + kFilterStiffening * 4.0) / (kSemiImplicitShare * 8.0));
  EXPECT_DOUBLE_EQ(filter_scale(3.0, 4.0, 8.0, kFilterStiffening).scale,
                   kSpectralMargin * 3.0 / (kSemiImplicitShare * 8.0));
  // During a run the allowance follows the tangent growth, never below the set-up's.
  EXPECT_EQ(filter_stiffening(0.0), kFilterStiffening);
  EXPECT_EQ(filter_stiffening(0.9 * kFilterStiffening / kStiffeningPerGrowth),
            kFilterStiffening);
  EXPECT_DOUBLE_EQ(filter_stiffening(2.0), 2.0 * kStiffeningPerGrowth);
  // With time levels the proven bound grows from the thesis' quarter by the same share of g.
  EXPECT_EQ(time_level_stiffening(0.0), 1.0);
  EXPECT_DOUBLE_EQ(kSemiImplicitShare * time_level_stiffening(2.0),
                   kSemiImplicitShare + 2.0 * kStiffeningPerGrowth);
}

TEST(SpectralBound, FilterSpectrumFollowsTheGrowthOfAStiffeningLawOnly) {
  MaterialLaw law = law_with(5e4, 1e4);
  const TetMesh mesh = jittered_box(3, 2, 2, 0.2, 2);
  const LevelModel cauchy = build_level_model(mesh, law, true);
  EXPECT_EQ(filter_spectrum_at(cauchy, 2.0).scale, cauchy.filter_spectrum.scale);
  law.strain = StrainMeasure::GreenLagrange;
  const LevelModel green = build_level_model(mesh, law, true);
  EXPECT_DOUBLE_EQ(filter_spectrum_at(green, 0.0).scale, green.filter_spectrum.scale);
  const double lambda_f = green.filter_spectrum.eigenvalue;
  const double lambda_k = green.stiffness_spectrum.eigenvalue;
  const double grown = filter_spectrum_at(green, 2.0).scale;
  EXPECT_GT(grown, green.filter_spectrum.scale);
  EXPECT_NEAR(grown * kSemiImplicitShare * green.filter_spectrum.star_max,
              lambda_f + std::max((kSpectralMargin - 1) * std::abs(lambda_f), 2.0 * kStiffeningPerGrowth * lambda_k),
              1e-9 * lambda_k);
}

TEST(SpectralBound, ExplicitBoundsGrowBeyondWhatTheMarginCovers) {
  // One global explicit step stands for kSpectralMargin times the rest spectrum; the deformed
  // tangent is below (1 + g) times the rest bound (physics/tangent_growth.hpp), the damping's
  // below 1 + g_d, with a margin of √kSpectralMargin on it. Below that nothing moves.
  const GrowthsNeeded covered = explicit_growths_needed();
  EXPECT_DOUBLE_EQ(covered.stiffness_above, kSpectralMargin - 1);
  EXPECT_DOUBLE_EQ(covered.damping_above, std::sqrt(kSpectralMargin) - 1);
  for (const double g : {0.0, 0.3, covered.stiffness_above}) EXPECT_EQ(explicit_stiffening(g), 1.0);
  for (const double g : {0.0, 0.2, covered.damping_above}) EXPECT_EQ(explicit_damping_growth(g), 1.0);
  EXPECT_DOUBLE_EQ(explicit_stiffening(2.0), 3.0 / kSpectralMargin);
  EXPECT_DOUBLE_EQ(explicit_damping_growth(1.0), 2.0 / std::sqrt(kSpectralMargin));
  MaterialLaw law = law_with(5e4, 1e4, 0, 5);
  law.strain = StrainMeasure::GreenLagrange;
  const LevelModel m = build_level_model(jittered_box(3, 2, 2, 0.2, 2), law);
  const PointInertia rest = calibrated(m.star[0], m, false, false);
  for (const bool time_levels : {false, true}) {
    const PointInertia at_rest = calibrated(m.star[0], m, false, time_levels);
    const PointInertia grown = calibrated(m.star[0], m, false, time_levels, 8.0, 3.0);
    EXPECT_DOUBLE_EQ(grown.stiffness, at_rest.stiffness * 9.0 / kSpectralMargin);
    EXPECT_DOUBLE_EQ(grown.damping, at_rest.damping * 4.0 / std::sqrt(kSpectralMargin));
    const PointInertia small = calibrated(m.star[0], m, false, time_levels, 0.4, 0.2);
    EXPECT_EQ(small.stiffness, at_rest.stiffness);
    EXPECT_EQ(small.damping, at_rest.damping);
  }
  EXPECT_GT(rest.damping, 0.0);
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
  // After calibration the largest ω_i² of the level is kSpectralMargin × λ_max (dense): the
  // level alone is estimated within the margin, where the star sums alone were 2–2.5 times above
  // it. The damping bounds are scaled at most to the margin too (less: CombinedLimit… below).
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
  EXPECT_LE(c_max / omega_max_squared(m, true), kSpectralMargin * (1 + 2e-3));
  EXPECT_NEAR(m.damping_spectrum.star_max * m.damping_spectrum.scale / omega_max_squared(m, true),
              kSpectralMargin, 2e-3);
  EXPECT_GT(m.stiffness_spectrum.star_max / m.stiffness_spectrum.eigenvalue, 1.5);
}

namespace {

// The dense truth of combined_step_limit(): the largest dt with λ_max(M⁻¹(dt²A + 2dt C)) ≤ 4,
// over the points not `held` (all when empty).
double dense_combined_limit(const LevelModel& m, bool filtered,
                            const std::vector<std::uint8_t>& held = {}) {
  auto top = [&](double dt) {
    const Eigen::MatrixXd A = dense_operator(m, m.K, filtered ? 1.0 : -1.0, dt * dt) +
                              dense_operator(m, m.D, -1.0, 2 * dt);
    return largest_eigenvalue(held.empty() ? A : free_block(A, held));
  };
  double lo = 1e-7, hi = 1.0;
  for (int k = 0; k < 60; ++k) {
    const double mid = std::sqrt(lo * hi);
    (top(mid) <= 4 ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

TEST(SpectralBound, CombinedLimitOfDampingAndStiffnessTogether) {
  // Damping peaks on other modes than the (filtered) stiffness: the level's combined limit is
  // longer than the one from the two maxima apart. Lanczos + bisection match the dense truth
  // from below within 1.5 %, and the calibrated point steps of the level then peak at it over
  // √kSpectralMargin: never optimistic, and no looser than the undamped calibration.
  for (bool semi : {false, true}) {
    const LevelModel m =
        build_level_model(jittered_box(6, 3, 3, 0.25, 7), law_with(5e4, 1e4, 0, 20), semi);
    const SpectralScale& k = semi ? m.filter_spectrum : m.stiffness_spectrum;
    const double limit = combined_step_limit(m.adj, m.K, m.D, m.mass, semi, k.eigenvalue,
                                             m.damping_spectrum.eigenvalue);
    const double truth = dense_combined_limit(m, semi);
    EXPECT_LE(limit, truth * (1 + 1e-9)) << "semi " << semi;
    EXPECT_GE(limit, truth / 1.015) << "semi " << semi;
    double step = std::numeric_limits<double>::infinity();
    for (const PointInertia& p : m.star)
      step = std::min(step, stable_step_of(calibrated(p, m, semi), semi));
    EXPECT_LE(step, truth / std::sqrt(kSpectralMargin) * (1 + 1e-3)) << "semi " << semi;
    EXPECT_GE(step, truth / std::sqrt(kSpectralMargin) / 1.02) << "semi " << semi;
    EXPECT_LE(m.step_damping_scale, m.damping_spectrum.scale);
    std::printf("%s: combined limit %.4g s, apart %.4g s, damping scale %.3f of %.3f\n",
                semi ? "semi-implicit" : "explicit", truth,
                4 / (m.damping_spectrum.eigenvalue +
                     std::sqrt(std::pow(m.damping_spectrum.eigenvalue, 2) + 4 * k.eigenvalue)),
                m.step_damping_scale, m.damping_spectrum.scale);
  }
}

TEST(SpectralBound, HeldPointsAreLeftOutOfTheLevelsSpectra) {
  // A level held on a face (scenario `fixed`): its spectra are those of the free points, which
  // the step has to keep stable, matched from above against the dense operator with the held
  // rows and columns removed. Holding only lowers them, so the level's combined limit lengthens
  // (liver_thesis' base held: 1.69× for the semi-implicit finest level), and the calibrated
  // steps of the free points peak at it over √kSpectralMargin as for a free level.
  // Cells graded towards the held face (x = 0, the thinnest layer 1/36 of the length): the
  // level's fastest modes are there, as at liver_thesis' base.
  TetMesh mesh = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.04, 0.03), 6, 3, 3);
  for (Vec3& p : mesh.points) p.x() = 10 * p.x() * p.x();
  std::vector<std::uint8_t> held(mesh.points.size(), 0);
  for (size_t i = 0; i < held.size(); ++i) held[i] = mesh.points[i].x() < 1e-9 ? 1 : 0;
  for (bool semi : {false, true}) {
    const LevelModel m = build_level_model(mesh, law_with(5e4, 1e4, 0, 20), semi, held);
    const LevelModel whole = build_level_model(mesh, law_with(5e4, 1e4, 0, 20), semi);
    ASSERT_EQ(m.held, held);
    const double k = largest_eigenvalue(free_block(dense_operator(m, m.K), held));
    EXPECT_GE(m.stiffness_spectrum.eigenvalue, k * (1 - 1e-9));
    EXPECT_LE(m.stiffness_spectrum.eigenvalue, k * (1 + 2e-3));
    EXPECT_LT(m.stiffness_spectrum.eigenvalue, whole.stiffness_spectrum.eigenvalue);
    const double c = largest_eigenvalue(free_block(dense_operator(m, m.D), held));
    EXPECT_GE(m.damping_spectrum.eigenvalue, c * (1 - 1e-9));
    EXPECT_LE(m.damping_spectrum.eigenvalue, c * (1 + 2e-3));
    if (semi) {
      const double f = largest_eigenvalue(free_block(dense_operator(m, m.K, 1.0), held));
      EXPECT_GE(m.filter_spectrum.eigenvalue, f - 1e-9 * k);
      EXPECT_LE(m.filter_spectrum.eigenvalue, f + 2e-3 * k);
    }
    // The point bounds compared are the free points' too.
    double star_max = 0, step = std::numeric_limits<double>::infinity();
    double whole_step = step;
    for (int i = 0; i < m.num_points(); ++i) {
      whole_step = std::min(whole_step, stable_step_of(calibrated(whole.star[i], whole, semi), semi));
      if (held[i]) continue;
      star_max = std::max(star_max, m.star[i].stiffness / m.star[i].mass);
      step = std::min(step, stable_step_of(calibrated(m.star[i], m, semi), semi));
    }
    EXPECT_EQ(m.stiffness_spectrum.star_max, star_max);
    const double truth = dense_combined_limit(m, semi, held);
    EXPECT_GT(truth, dense_combined_limit(m, semi)) << "semi " << semi;
    EXPECT_LE(step, truth / std::sqrt(kSpectralMargin) * (1 + 1e-3)) << "semi " << semi;
    EXPECT_GE(step, truth / std::sqrt(kSpectralMargin) / 1.02) << "semi " << semi;
    EXPECT_GT(step, whole_step) << "semi " << semi;
    std::printf("%s: held face, combined limit %.4g s (free level %.4g s), λ_K %.4g (%.4g)\n",
                semi ? "semi-implicit" : "explicit", truth, dense_combined_limit(whole, semi),
                m.stiffness_spectrum.eigenvalue, whole.stiffness_spectrum.eigenvalue);
  }
  // A mask of another level is a programming error.
  EXPECT_THROW(build_level_model(mesh, law_with(5e4, 1e4), false, {1, 0}), std::logic_error);
}
