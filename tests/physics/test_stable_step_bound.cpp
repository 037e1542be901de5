// The stable-step estimate of a point (physics/stable_step_bound.hpp) against the truth: the
// largest eigenvalue of M⁻¹K of the assembled single-level model (dense), and the damped limit
// of a kick-drift step on one oscillator. The bound must never be optimistic (a step at the
// estimate is stable) and not too pessimistic (issue 15: true limit / estimate in [1, 2.5]).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

#include "mesh/box_mesh.hpp"
#include "physics/level_model.hpp"

using namespace mrsim;

namespace {

MaterialLaw law_with(double lambda, double mu, double phi = 0, double psi = 0) {
  MaterialLaw law;
  law.strain = StrainMeasure::Cauchy;
  law.lambda = lambda;
  law.mu = mu;
  law.phi = phi;
  law.psi = psi;
  law.density = 1000;
  return law;
}

TetMesh jittered_box(int nx, int ny, int nz, double jitter, unsigned seed) {
  TetMesh m = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.04, 0.03), nx, ny, nz);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-jitter, jitter);
  const Vec3 h(0.1 / nx, 0.04 / ny, 0.03 / nz);
  for (Vec3& p : m.points)
    if (p.x() > 1e-9 && p.x() < 0.1 - 1e-9 && p.y() > 1e-9 && p.y() < 0.04 - 1e-9 && p.z() > 1e-9 &&
        p.z() < 0.03 - 1e-9)
      p += Vec3(d(rng) * h.x(), d(rng) * h.y(), d(rng) * h.z());
  return m;
}

// ω_max² of the free (unsupported) level: the largest eigenvalue of M^-1/2 K M^-1/2.
double omega_max_squared(const LevelModel& m, bool damping = false) {
  const int n = m.num_points();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  const auto& blocks = damping ? m.D : m.K;
  for (int i = 0; i < n; ++i)
    for (int e = m.adj.nbr_start[i]; e < m.adj.nbr_start[i + 1]; ++e) {
      const int j = m.adj.nbr[e];
      K.block<3, 3>(3 * i, 3 * j) += blocks[e];
      K.block<3, 3>(3 * i, 3 * i) -= blocks[e];
    }
  for (int i = 0; i < 3 * n; ++i)
    for (int j = 0; j < 3 * n; ++j) K(i, j) /= std::sqrt(m.mass[i / 3] * m.mass[j / 3]);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(K, Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff();
}

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
    EXPECT_GE(m.bounds.stiffness[t], top * (1 - 1e-12));
    EXPECT_LE(m.bounds.stiffness[t], 3 * top);
  }
}
