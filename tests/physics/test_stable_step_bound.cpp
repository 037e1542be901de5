// The stable-step estimate of a point (physics/stable_step_bound.hpp) against the truth: the
// largest eigenvalue of M⁻¹K of the assembled single-level model (dense), and the damped limit
// of a kick-drift step on one oscillator. The bound must never be optimistic (a step at the
// estimate is stable) and not too pessimistic (issue 15: true limit / estimate in [1, 2.5]).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

#include "physics/dense_spectrum.hpp"
#include "physics/level_model.hpp"

using namespace mrsim;
using namespace mrsim::test_support;

namespace {

double estimate(const LevelModel& m, bool semi = false) {
  double dt = INFINITY;
  for (const PointInertia& p : m.star) dt = std::min(dt, stable_step_of(p, semi));
  return dt;
}

}  // namespace

TEST(StableStepBound, NeverOptimisticAndWithinTwoAndAHalfOfTheTrueLimit) {
  struct Case {
    TetMesh mesh;
    MaterialLaw law;
  };
  std::vector<Case> cases;
  cases.push_back({make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), 10, 2, 2),
                   law_with(576923, 384615)});  // validation beam, ν = 0.3
  cases.push_back({jittered_box(6, 3, 3, 0.25, 3), law_with(5e4, 1e4)});
  cases.push_back({jittered_box(5, 3, 2, 0.3, 8), law_with(0, 1e4)});
  cases.push_back({jittered_box(5, 2, 2, 0.2, 5), law_with(5e5, 1e4)});  // ν = 0.49
  for (const Case& c : cases) {
    const LevelModel m = build_level_model(c.mesh, c.law);
    const double truth = 2.0 / std::sqrt(omega_max_squared(m));
    const double est = estimate(m);
    EXPECT_GE(truth / est, 1.0) << "lambda " << c.law.lambda;
    EXPECT_LE(truth / est, 2.5) << "lambda " << c.law.lambda;
    // Calibrated by the level's spectrum (one global step, physics/spectral_bound.hpp): the
    // level alone sits at √kSpectralMargin of its true limit; the star bounds gave 1.33–1.60.
    double calibrated_est = INFINITY;
    for (const PointInertia& p : m.star)
      calibrated_est = std::min(calibrated_est, stable_step_of(calibrated(p, m), false));
    EXPECT_NEAR(truth / calibrated_est, std::sqrt(kSpectralMargin), 0.01)
        << "lambda " << c.law.lambda;
    RecordProperty("true_over_estimate_lambda_" + std::to_string(int(c.law.lambda)),
                   std::to_string(truth / est));
  }
}

TEST(StableStepBound, DampedLimitOfOneOscillatorIsExact) {
  // ẍ + γẋ + ω²x = 0, kick (with the damping force at the old velocity) then drift: stable up
  // to 4 / (γ + √(γ² + 4ω²)), unstable just above, whatever ζ.
  for (double zeta : {0.0, 0.3, 2.0, 20.0}) {
    const double omega = 100.0, gamma = 2 * zeta * omega;
    const PointInertia p{2.0, 2.0 * omega * omega, 2.0 * gamma};
    const double limit = stable_step_of(p, false);
    EXPECT_NEAR(limit, 2.0 / omega * (std::sqrt(1 + zeta * zeta) - zeta), 1e-12 * limit);
    // Growth of the amplitude from the first to the last thousand steps (near the limit the
    // bounded orbit of the symplectic step is a long ellipse: compare like with like).
    auto grows = [&](double dt) {
      double x = 1, v = 0, first = 0, last = 0;
      for (int k = 0; k < 20000; ++k) {
        v += dt * (-omega * omega * x - gamma * v);
        x += dt * v;
        const double a = std::abs(x) + std::abs(v) * dt;
        if (!std::isfinite(a) || a > 1e6) return true;
        (k < 1000 ? first : last) = std::max(k < 1000 ? first : last, a);
        if (k < 19000) last = 0;
      }
      return last > 2 * first;
    };
    EXPECT_FALSE(grows(0.999 * limit)) << "zeta " << zeta;
    EXPECT_TRUE(grows(1.01 * limit)) << "zeta " << zeta;
  }
}

TEST(StableStepBound, DampingShortensTheEstimateAsTheDampedLimitSays) {
  const TetMesh mesh = jittered_box(5, 3, 2, 0.2, 2);
  const LevelModel plain = build_level_model(mesh, law_with(0, 1e4));
  const LevelModel damped = build_level_model(mesh, law_with(0, 1e4, 0, 20));
  // ψ = 20 Pa·s on 2 cm cells: ζ of the highest mode > 1, the step shrinks by √(1+ζ²) − ζ.
  EXPECT_LT(estimate(damped), 0.5 * estimate(plain));
  // Never optimistic against the damped modal truth: the highest mode of D (∝ K here, φ/ψ =
  // λ/μ = 0) gives γ_max = (ψ/μ) ω_max², so the true limit is the one-oscillator formula.
  const double w2 = omega_max_squared(plain);
  const double gamma = 20.0 / 1e4 * w2;
  const double truth = 4.0 / (gamma + std::sqrt(gamma * gamma + 4 * w2));
  EXPECT_GE(truth / estimate(damped), 1.0);
  EXPECT_LE(truth / estimate(damped), 2.5);
}

TEST(StableStepBound, SemiImplicitDoublesTheUndampedEstimate) {
  const LevelModel m = build_level_model(jittered_box(4, 2, 2, 0.2, 1), law_with(5e4, 1e4));
  EXPECT_NEAR(estimate(m, true), 2 * estimate(m), 1e-12 * estimate(m));
}

TEST(StableStepBound, TheFilterTakesTheElasticStiffnessNotTheContactPenalty) {
  // The semi-implicit filter probes J_i at rest without tools: a contact penalty stays explicit,
  // so it shortens the semi-implicit step as much as the explicit one.
  PointInertia contact_only;
  contact_only.mass = 2.0;
  contact_only.contact_stiffness = 8.0e4;
  EXPECT_DOUBLE_EQ(stable_step_of(contact_only, true), stable_step_of(contact_only, false));
  EXPECT_DOUBLE_EQ(stable_step_of(contact_only, false), 2.0 / 200.0);
  PointInertia elastic = contact_only;
  std::swap(elastic.stiffness, elastic.contact_stiffness);
  EXPECT_DOUBLE_EQ(stable_step_of(elastic, true), 2.0 * stable_step_of(elastic, false));
  // A calibrated semi-implicit stiffness below zero (ω² = -5000 /s²): no elastic limit; with
  // damping γ = 200 /s the smallest root of dt²ω² + 2 dt γ = 4.
  elastic.stiffness = -4.0e4;
  EXPECT_TRUE(std::isinf(stable_step_of(elastic, true)));
  elastic.damping = 400.0;
  const double dt = stable_step_of(elastic, true);
  EXPECT_DOUBLE_EQ(dt, 4.0 / (200.0 + std::sqrt(200.0 * 200.0 - 4 * 5000.0)));
  EXPECT_NEAR(-5000.0 * dt * dt + 2 * 200.0 * dt, 4.0, 1e-12);
  EXPECT_GT(dt, 2.0 / 200.0);  // longer than the damping limit alone
}

TEST(StableStepBound, StarValuesAreTheLumpedMassAndFourTimesTheTetBounds) {
  const LevelModel m = build_level_model(jittered_box(3, 2, 2, 0.2, 4), law_with(5e4, 1e4));
  double tets = 0, star = 0;
  for (double d : m.bounds.stiffness) tets += d;
  for (int i = 0; i < m.num_points(); ++i) {
    EXPECT_EQ(m.star[i].mass, m.mass[i]);  // bit for bit: single-level runs are unchanged
    star += m.star[i].stiffness;
  }
  EXPECT_NEAR(star, 4 * tets, 1e-12 * tets);
}

TEST(StableStepBound, TetBoundIsAboveTheLargestEigenvalueOfItsStiffness) {
  // d_t ≥ λ_max(K_t) for every tet of a jittered mesh, and close for a regular one.
  const LevelModel m = build_level_model(jittered_box(3, 2, 2, 0.3, 6), law_with(5e4, 1e4));
  const TetEnergyBounds& bounds = m.bounds;
  for (int t = 0; t < m.num_tets(); ++t) {
    Eigen::Matrix<double, 12, 12> K = Eigen::Matrix<double, 12, 12>::Zero();
    const auto& g = m.geo.grad[t];
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        K.block<3, 3>(3 * a, 3 * b) =
            m.geo.volume[t] * (5e4 * g[a] * g[b].transpose() + 1e4 * g[b] * g[a].transpose() +
                               1e4 * g[a].dot(g[b]) * Mat3::Identity());
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>> es(K, Eigen::EigenvaluesOnly);
    const double top = es.eigenvalues().maxCoeff();
    EXPECT_GE(bounds.stiffness[t], top * (1 - 1e-12));
    EXPECT_LE(bounds.stiffness[t], 3 * top);
  }
}
