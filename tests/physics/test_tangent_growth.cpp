// The tangent growth g of a Green–Lagrange tet (physics/tangent_growth.hpp): the stiffness at a
// deformed state stays below (1 + g) times the rest energy bound d_t, a rigid motion does not
// grow it, and the closed form of a uniaxial stretch. The semi-implicit step follows g
// (physics/spectral_bound.hpp filter_stiffening()), so an optimistic g is an unstable run.
// The same for the strain-rate damping and its growth g_d, which scales each point's damping
// bound when semi-implicit.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "physics/dense_spectrum.hpp"
#include "physics/stress.hpp"
#include "physics/tangent_growth.hpp"

using namespace mrsim;
using namespace mrsim::test_support;

namespace {

MaterialLaw green(double lambda, double mu) {
  MaterialLaw law = law_with(lambda, mu);
  law.strain = StrainMeasure::GreenLagrange;
  return law;
}

Mat3 rotation(double a, double b, double c) {
  return (Eigen::AngleAxisd(a, Vec3::UnitZ()) * Eigen::AngleAxisd(b, Vec3::UnitY()) *
          Eigen::AngleAxisd(c, Vec3::UnitX()))
      .toRotationMatrix();
}

// Nodal forces' derivative (12×12, symmetrised) of one tet at displacement gradient G, by
// central differences: the tangent stiffness whose largest eigenvalue sets the step.
Eigen::Matrix<double, 12, 12> tangent(const TetGradients& g, double volume, const Mat3& G,
                                      const MaterialLaw& law) {
  auto forces = [&](const Mat3& Gu) {
    const Mat3 P = green_piola(Gu, nullptr, law);
    Eigen::Matrix<double, 12, 1> f;
    for (int a = 0; a < 4; ++a) f.segment<3>(3 * a) = volume * P * g[a];
    return f;
  };
  const double h = 1e-7;
  Eigen::Matrix<double, 12, 12> K;
  for (int b = 0; b < 4; ++b)
    for (int j = 0; j < 3; ++j) {
      const Mat3 dG = h * Vec3::Unit(j) * g[b].transpose();  // u_b += h e_j
      K.col(3 * b + j) = (forces(G + dG) - forces(G - dG)) / (2 * h);
    }
  return 0.5 * (K + K.transpose());
}

// The damping matrix (12×12, symmetrised) of one tet at displacement gradient G: the nodal
// forces are linear in the velocities, so unit velocities give its columns exactly.
Eigen::Matrix<double, 12, 12> damping_tangent(const TetGradients& g, double volume, const Mat3& G,
                                              const MaterialLaw& law) {
  auto forces = [&](const Mat3& Gdot) {
    const Mat3 P = green_piola(G, &Gdot, law) - green_piola(G, nullptr, law);
    Eigen::Matrix<double, 12, 1> f;
    for (int a = 0; a < 4; ++a) f.segment<3>(3 * a) = volume * P * g[a];
    return f;
  };
  Eigen::Matrix<double, 12, 12> C;
  for (int b = 0; b < 4; ++b)
    for (int j = 0; j < 3; ++j) C.col(3 * b + j) = forces(Vec3::Unit(j) * g[b].transpose());
  return 0.5 * (C + C.transpose());
}

// A random rotation–stretch–rotation gradient F − I, principal stretches in [0.7, 1.5].
Mat3 random_gradient(std::mt19937& rng) {
  std::uniform_real_distribution<double> angle(-3.0, 3.0), stretch(0.7, 1.5);
  const Vec3 s(stretch(rng), stretch(rng), stretch(rng));
  const Mat3 F = rotation(angle(rng), angle(rng), angle(rng)) * s.asDiagonal() *
                 rotation(angle(rng), angle(rng), angle(rng)).transpose();
  return F - Mat3::Identity();
}

double top(const Eigen::Matrix<double, 12, 12>& K) {
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>>(K, Eigen::EigenvaluesOnly)
      .eigenvalues()
      .maxCoeff();
}

// Over every tet of `m` and 4 random gradients G each: expects λ_max(matrix(t, G)) at most
// (1 + growth(G)) bound[t] (1 + tol), and returns the largest λ_max(matrix(t, G)) over
// λ_max(matrix(t, 0)), so a caller can check that the growth is real.
template <class Matrix, class Growth>
double largest_deformed_over_rest(const LevelModel& m, std::mt19937& rng, Matrix matrix,
                                  Growth growth, const std::vector<double>& bound, double tol,
                                  const std::string& what) {
  double most = 0;
  for (int t = 0; t < m.num_tets(); ++t) {
    const double rest = top(matrix(t, Mat3::Zero()));
    for (int trial = 0; trial < 4; ++trial) {
      const Mat3 G = random_gradient(rng);
      const double g = growth(G);
      const double deformed = top(matrix(t, G));
      EXPECT_LE(deformed, (1 + g) * bound[t] * (1 + tol)) << what << " tet " << t << " g " << g;
      most = std::max(most, deformed / rest);
    }
  }
  return most;
}

}  // namespace

TEST(TangentGrowth, RigidRotationDoesNotGrow) {
  const MaterialLaw law = green(5e4, 1e4);
  for (double a : {0.3, 1.2, 2.9})
    EXPECT_NEAR(tangent_growth(rotation(a, 0.5 * a, -a) - Mat3::Identity(), law), 0.0, 1e-12);
}

TEST(TangentGrowth, UniaxialStretchIsThreeTimesTheStrain) {
  // E = ½(s² − 1) e_x e_x: σ_max(F)² − 1 = 2E and s_max(S) = (λ + 2μ) E, so g = 3E.
  const MaterialLaw law = green(5e4, 1e4);
  for (double s : {1.05, 1.2, 1.5}) {
    Mat3 G = Mat3::Zero();
    G(0, 0) = s - 1;
    EXPECT_NEAR(tangent_growth(G, law), 1.5 * (s * s - 1), 1e-12);
  }
  Mat3 squeeze = Mat3::Zero();
  squeeze(0, 0) = -0.2;  // compression softens: no growth
  EXPECT_NEAR(tangent_growth(squeeze, law), 0.0, 1e-8);
}

TEST(TangentGrowth, DeformedTangentStaysBelowTheGrownRestBound) {
  // λ_max(K_t(F)) ≤ (1 + g) d_t for random rotations and stretches of every tet of a jittered
  // mesh, nearly incompressible or not; and the growth is real (the deformed tangent of the
  // largest stretches exceeds the rest one by more than half), so the bound is not vacuous.
  std::mt19937 rng(7);
  for (double lambda : {0.0, 5e4, 5e5}) {
    const MaterialLaw law = green(lambda, 1e4);
    const LevelModel m = build_level_model(jittered_box(2, 2, 2, 0.3, 3), law);
    const double most = largest_deformed_over_rest(
        m, rng, [&](int t, const Mat3& G) { return tangent(m.geo.grad[t], m.geo.volume[t], G, law); },
        [&](const Mat3& G) { return tangent_growth(G, law); }, m.bounds.stiffness, 1e-6,
        "lambda " + std::to_string(lambda));
    EXPECT_GT(most, 1.5) << "lambda " << lambda;
  }
}

TEST(TangentGrowth, LargestOverTetsIsTheMostStretchedTet) {
  const MaterialLaw law = green(5e4, 1e4);
  const TetMesh mesh = jittered_box(2, 2, 2, 0.2, 5);
  const LevelModel m = build_level_model(mesh, law);
  std::vector<int> all(m.num_tets());
  for (int t = 0; t < m.num_tets(); ++t) all[t] = t;
  const int n = m.num_points();
  std::vector<Vec3> u(n);
  for (int i = 0; i < n; ++i) u[i] = Vec3(0.1 * mesh.points[i].x(), 0, 0);  // 10 % along x
  EXPECT_NEAR(largest_tangent_growth(m.geo, all, u, law), 1.5 * (1.1 * 1.1 - 1), 1e-9);
  // One vertex pulled further out: its tets grow more, and the largest is theirs.
  const int far = 5;
  u[far] += Vec3(0, 0.004, 0);
  double top = 0;
  for (int t = 0; t < m.num_tets(); ++t)
    top = std::max(top, tangent_growth(tet_gradient(m.geo.grad[t], m.geo.tets[t], u.data()), law));
  EXPECT_GT(top, 1.5 * (1.1 * 1.1 - 1) + 0.01);
  EXPECT_EQ(largest_tangent_growth(m.geo, all, u, law), top);
  EXPECT_EQ(largest_tangent_growth(m.geo, {}, u, law), 0.0);
}

TEST(TangentGrowth, DeformedDampingStaysBelowTheGrownRestBound) {
  // λ_max(C(F)) ≤ (1 + g_d) d_t^C with g_d = σ_max(F)² − 1, for random rotations and stretches;
  // g_d of a rotation is 0 and of a uniaxial stretch s is s² − 1; and the growth is real (the
  // deformed damping of the largest stretches exceeds the rest one by more than half), so a
  // damping bound that ignored it would be optimistic.
  std::mt19937 rng(11);
  for (double phi : {0.0, 20.0}) {
    const MaterialLaw law = green(5e4, 1e4);
    MaterialLaw damped = law_with(5e4, 1e4, phi, 5.0);
    damped.strain = StrainMeasure::GreenLagrange;
    const LevelModel m = build_level_model(jittered_box(2, 2, 2, 0.3, 3), damped);
    const double most = largest_deformed_over_rest(
        m, rng,
        [&](int t, const Mat3& G) {
          return damping_tangent(m.geo.grad[t], m.geo.volume[t], G, damped);
        },
        [&](const Mat3& G) {
          const double g_d = damping_growth(G);
          EXPECT_LE(g_d, tangent_growth(G, law) + 1e-12);  // the material part of g
          return g_d;
        },
        m.bounds.damping, 1e-9, "phi " + std::to_string(phi));
    EXPECT_GT(most, 1.5) << "phi " << phi;
  }
  EXPECT_NEAR(damping_growth(rotation(1.1, -0.4, 2.0) - Mat3::Identity()), 0.0, 1e-12);
  Mat3 G = Mat3::Zero();
  G(1, 1) = 0.3;
  EXPECT_NEAR(damping_growth(G), 1.3 * 1.3 - 1, 1e-12);
}

TEST(TangentGrowth, PointsTakeTheLargestGrowthsOfTheirListedTets) {
  const MaterialLaw law = green(5e4, 1e4);
  const TetMesh mesh = jittered_box(2, 2, 2, 0.2, 5);
  const LevelModel m = build_level_model(mesh, law);
  const int n = m.num_points();
  std::vector<Vec3> u(n, Vec3::Zero());
  const int far = 5;
  u[far] = Vec3(0, 0.004, 0);
  // Only the tets of `far` and one tet without it are listed.
  std::vector<int> listed;
  int other = -1;
  for (int t = 0; t < m.num_tets(); ++t) {
    const auto& tet = m.geo.tets[t];
    if (std::find(tet.begin(), tet.end(), far) != tet.end())
      listed.push_back(t);
    else if (other < 0)
      other = t;
  }
  listed.push_back(other);
  std::sort(listed.begin(), listed.end());
  std::vector<double> stiffness(n, -1.0), damping(n, -1.0);  // -1: not written
  const double g = tangent_growths_of(m.geo, listed, u, law, stiffness, damping);
  EXPECT_EQ(g, largest_tangent_growth(m.geo, listed, u, law));
  std::vector<double> expected(n, -1.0), expected_g(n, -1.0);
  for (int t : listed)
    for (int a : m.geo.tets[t]) {
      const Mat3 grad_u = tet_gradient(m.geo.grad[t], m.geo.tets[t], u.data());
      expected[a] = std::max(expected[a] < 0 ? 0.0 : expected[a], damping_growth(grad_u));
      const std::array<int, 1> one{t};
      expected_g[a] = std::max(expected_g[a] < 0 ? 0.0 : expected_g[a],
                               largest_tangent_growth(m.geo, one, u, law));
    }
  for (int i = 0; i < n; ++i) {
    EXPECT_EQ(damping[i], expected[i]) << "point " << i;
    EXPECT_EQ(stiffness[i], expected_g[i]) << "point " << i;
  }
  EXPECT_GT(stiffness[far], 0.01);
  EXPECT_EQ(*std::max_element(stiffness.begin(), stiffness.end()), g);
  EXPECT_GT(damping[far], 0.01);
  EXPECT_EQ(std::count(damping.begin(), damping.end(), -1.0),
            std::count(expected.begin(), expected.end(), -1.0));
  EXPECT_GT(std::count(damping.begin(), damping.end(), -1.0), 0);  // unlisted points untouched
}

TEST(TangentGrowth, GrowthsBelowWhatIsNeededMayBeBoundsAndAboveItAreExact) {
  // The explicit schemes count no growth below their spectral margin's (physics/
  // spectral_bound.hpp explicit_growths_needed()): there a Gershgorin bound on e_max replaces
  // the eigenvalue solve. What is reported must bound the exact growth and, wherever either
  // could matter, be it.
  const MaterialLaw law = green(5e4, 1e4);
  const TetMesh mesh = jittered_box(3, 2, 2, 0.2, 8);
  const LevelModel m = build_level_model(mesh, law);
  const int n = m.num_points();
  const GrowthsNeeded needed{0.5, 0.2247};
  std::mt19937 rng(11);
  int bounded = 0, exact_above = 0;
  for (const double scale : {1e-4, 3e-3, 1e-2, 3e-2}) {
    std::normal_distribution<double> d(0, scale);
    std::vector<Vec3> u(n);
    for (Vec3& x : u) x = Vec3(d(rng), d(rng), d(rng));
    for (int t = 0; t < m.num_tets(); ++t) {
      const std::array<int, 1> one{t};
      std::vector<double> g(n), g_d(n), exact(n), exact_d(n);
      tangent_growths_of(m.geo, one, u, law, g, g_d, needed);
      tangent_growths_of(m.geo, one, u, law, exact, exact_d);
      const int a = m.geo.tets[t][0];
      const bool same = g[a] == exact[a] && g_d[a] == exact_d[a];
      if (exact[a] > needed.stiffness_above || exact_d[a] > needed.damping_above) {
        EXPECT_TRUE(same) << "tet " << t << ": " << g[a] << " / " << exact[a];
        ++exact_above;
      } else {
        EXPECT_GE(g[a], exact[a]) << "tet " << t;
        EXPECT_GE(g_d[a], exact_d[a]) << "tet " << t;
        EXPECT_LE(g[a], needed.stiffness_above) << "tet " << t;
        EXPECT_LE(g_d[a], needed.damping_above) << "tet " << t;
        bounded += !same;
      }
    }
  }
  EXPECT_GT(bounded, 0);      // the bound was used
  EXPECT_GT(exact_above, 0);  // and large growths were met
}
