// A calibrated level's orthotropic tensor (MaterialLaw::scales) through every path that reads
// the material: the Green–Lagrange kernel builds, the Cauchy edge matrices, the per-point
// force, the split stiffness of the calibration fit and its lowest-mode solver; and the per-tet
// tensors of object.calibration: per_tet (MaterialLaw::tet_tensors) through the same paths.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <vector>

#include "dense_spectrum.hpp"
#include "physics/component_stiffness.hpp"
#include "physics/green_nodal_forces.hpp"
#include "physics/internal_force.hpp"
#include "physics/lowest_modes.hpp"
#include "physics/stress.hpp"

namespace mrsim {
namespace {

using test_support::jittered_box;
using test_support::law_with;

const StiffnessScales kScales =
    StiffnessScales::from_components({0.7, 1.3, 0.4, 2.1, 0.9, 1.6, 0.5});

std::vector<Vec3> random_field(int n, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-amplitude, amplitude);
  std::vector<Vec3> u(n);
  for (Vec3& x : u) x = Vec3(d(rng), d(rng), d(rng));
  return u;
}

TEST(CalibratedLaw, ScalesRoundTripThroughTheirSevenComponents) {
  const auto c = kScales.components();
  EXPECT_EQ(StiffnessScales::from_components(c).mu, kScales.mu);
  EXPECT_EQ(kScales.mu[1], kScales.mu[3]);  // xy = yx
  EXPECT_EQ(kScales.mu[5], 0.9);            // yz
  EXPECT_DOUBLE_EQ(kScales.max_mu(), 2.1);
  EXPECT_TRUE(StiffnessScales{}.isotropic());
  EXPECT_FALSE(kScales.isotropic());
}

TEST(CalibratedLaw, GreenKernelBuildsGiveGreenPiolasBits) {
  const TetMesh mesh = jittered_box(5, 3, 3, 0.2, 3);
  MaterialLaw law = law_with(5e5, 3e4, 0.7, 20);
  law.strain = StrainMeasure::GreenLagrange;
  law.scales = kScales;
  const LevelModel m = build_level_model(mesh, law);
  const auto u = random_field(m.num_points(), 3e-3, 1), v = random_field(m.num_points(), 0.1, 2);
  std::vector<int> all(m.num_tets());
  for (int t = 0; t < m.num_tets(); ++t) all[t] = t;
  std::vector<TetGradients> out(m.num_tets());
  green_nodal_forces(m, all.data(), m.num_tets(), u.data(), v.data(), out.data());
  std::vector<TetGradients> base(m.num_tets());
  green_nodal_forces_baseline(green_kernel_data(m), all.data(), m.num_tets(),
                              reinterpret_cast<const double(*)[3]>(u.data()),
                              reinterpret_cast<const double(*)[3]>(v.data()),
                              reinterpret_cast<double(*)[4][3]>(base.data()));
  for (int t = 0; t < m.num_tets(); ++t) {
    const Mat3 G = tet_gradient(m.geo.grad[t], m.geo.tets[t], u.data());
    const Mat3 Gd = tet_gradient(m.geo.grad[t], m.geo.tets[t], v.data());
    const Mat3 P = -m.geo.volume[t] * green_piola(G, &Gd, law);
    TetGradients expected;
    for (int a = 0; a < 4; ++a) expected[a].noalias() = P * m.geo.grad[t][a];
    ASSERT_EQ(std::memcmp(&expected, &out[t], sizeof(TetGradients)), 0) << "tet " << t;
    ASSERT_EQ(std::memcmp(&expected, &base[t], sizeof(TetGradients)), 0) << "tet " << t;
  }
}

TEST(CalibratedLaw, GreenLagrangeMakesNoForceInARigidRotation) {
  const TetMesh mesh = jittered_box(5, 3, 3, 0.2, 4);
  MaterialLaw law = law_with(5e5, 3e4);
  law.strain = StrainMeasure::GreenLagrange;
  law.scales = kScales;
  const LevelModel m = build_level_model(mesh, law);
  const Mat3 R = Eigen::AngleAxisd(1.1, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  std::vector<Vec3> u(m.num_points()), stretch(m.num_points()), v(m.num_points(), Vec3::Zero());
  for (int i = 0; i < m.num_points(); ++i) {
    u[i] = (R - Mat3::Identity()) * mesh.points[i] + Vec3(0.01, -0.02, 0.03);
    stretch[i] = Vec3(0.01 * mesh.points[i].x(), 0, 0);
  }
  ForceWorkspace ws;
  std::vector<Vec3> f(m.num_points()), g(m.num_points());
  internal_forces(m, u.data(), v.data(), f.data(), ws);
  internal_forces(m, stretch.data(), v.data(), g.data(), ws);
  double fr = 0, gs = 0;
  for (int i = 0; i < m.num_points(); ++i)
    fr = std::max(fr, f[i].norm()), gs = std::max(gs, g[i].norm());
  EXPECT_LT(fr, 1e-10 * gs) << "a 1 % stretch gives " << gs << " N";
}

TEST(CalibratedLaw, CauchyEdgeMatricesAreTheTensorsForce) {
  const TetMesh mesh = jittered_box(4, 3, 3, 0.2, 5);
  MaterialLaw law = law_with(4e5, 2e4, 0.5, 12);
  law.scales = kScales;
  const LevelModel m = build_level_model(mesh, law);
  const auto u = random_field(m.num_points(), 1e-3, 6), v = random_field(m.num_points(), 0.1, 7);
  ForceWorkspace ws;
  std::vector<Vec3> f(m.num_points());
  internal_forces(m, u.data(), v.data(), f.data(), ws);  // edge matrices
  double scale = 0, err = 0;
  for (int i = 0; i < m.num_points(); ++i) {
    const Vec3 direct = point_internal_force(m, i, u.data(), v.data());  // per-tet stress
    scale = std::max(scale, direct.norm());
    err = std::max(err, (direct - f[i]).norm());
  }
  EXPECT_LT(err, 1e-12 * scale);
  // With unit scales the orthotropic matrices are the isotropic λA + μB.
  const std::vector<Mat3> iso =
      combined_edge_operators(m.geo, m.adj, {{law.lambda, law.mu}}).matrices[0];
  const std::vector<Mat3> ortho =
      orthotropic_edge_matrices(m.geo, m.adj, law.lambda, law.mu, StiffnessScales{});
  for (size_t e = 0; e < iso.size(); ++e)
    ASSERT_LT((iso[e] - ortho[e]).norm(), 1e-12 * iso[e].norm() + 1e-300) << "entry " << e;
}

TEST(CalibratedLaw, ComponentStiffnessSumsToTheLevelsLinearForce) {
  const TetMesh mesh = jittered_box(4, 3, 2, 0.2, 8);
  MaterialLaw law = law_with(4e5, 2e4);
  law.scales = kScales;
  const LevelModel m = build_level_model(mesh, law);
  std::vector<std::uint8_t> fixed(m.num_points(), 0);
  const ComponentStiffness cs = component_stiffness(m.geo, m.num_points(), law, fixed);
  const SparseMatrix K = cs.combined(kScales.components());
  const auto u = random_field(m.num_points(), 1e-3, 9);
  std::vector<Vec3> v(m.num_points(), Vec3::Zero()), f(m.num_points());
  ForceWorkspace ws;
  internal_forces(m, u.data(), v.data(), f.data(), ws);
  Eigen::VectorXd x(3 * m.num_points());
  for (int i = 0; i < m.num_points(); ++i) x.segment<3>(3 * i) = u[i];
  const Eigen::VectorXd Ku = K * x;
  for (int i = 0; i < m.num_points(); ++i)
    ASSERT_LT((Ku.segment<3>(3 * i) + f[i]).norm(), 1e-10 * Ku.norm()) << "point " << i;
  for (int i = 0; i < m.num_points(); ++i) EXPECT_DOUBLE_EQ(cs.mass[3 * i], m.mass[i]);
}

TEST(CalibratedLaw, LowestModesAreTheDenseOnes) {
  const TetMesh mesh = jittered_box(4, 2, 2, 0.2, 10);
  const MaterialLaw law = law_with(4e5, 2e4);
  for (const bool held : {true, false}) {
    std::vector<std::uint8_t> fixed(mesh.points.size(), 0);
    if (held)
      for (size_t i = 0; i < mesh.points.size(); ++i) fixed[i] = mesh.points[i].x() < 1e-9;
    const TetGeometry geo = build_tet_geometry(mesh);
    const ComponentStiffness cs =
        component_stiffness(geo, static_cast<int>(mesh.points.size()), law, fixed);
    const SparseMatrix K = cs.combined({1, 1, 1, 1, 1, 1, 1});
    const Modes modes = lowest_modes(K, cs.mass, 10);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(
        Eigen::MatrixXd(K), Eigen::MatrixXd(cs.mass.asDiagonal()));
    const double top = dense.eigenvalues().maxCoeff();
    for (int k = 0; k < 10; ++k)
      EXPECT_NEAR(modes.omega2[k], dense.eigenvalues()[k], 1e-9 * top)
          << (held ? "held" : "free") << " mode " << k;
    const Eigen::MatrixXd gram = modes.shapes.transpose() * cs.mass.asDiagonal() * modes.shapes;
    EXPECT_LT((gram - Eigen::MatrixXd::Identity(10, 10)).norm(), 1e-8);
  }
}

// Two levels of one mesh at the same random displacements u and velocities v: their forces.
struct BothForces {
  std::vector<Vec3> u, v, a, b;
};
BothForces forces_of_both(const LevelModel& a, const LevelModel& b, unsigned seed) {
  BothForces out{random_field(a.num_points(), 2e-3, seed), random_field(a.num_points(), 0.1, seed + 1),
                 std::vector<Vec3>(a.num_points()), std::vector<Vec3>(a.num_points())};
  ForceWorkspace ws;
  internal_forces(a, out.u.data(), out.v.data(), out.a.data(), ws);
  internal_forces(b, out.u.data(), out.v.data(), out.b.data(), ws);
  return out;
}

TetTensors random_tensors(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(std::log(0.3), std::log(3.0));
  TetTensors q(n);
  for (auto& t : q)
    for (double& x : t) x = std::exp(d(rng));
  return q;
}

// Each tet's seven factors make its elastic and damping forces and its stable-step bounds those
// of its own tensor (the level's times its factors), and change nothing of the masses or of the
// geometric weights (Laplacian criterion).
TEST(CalibratedLaw, PerTetTensorsGiveEachTetItsOwnStiffnessNotItsMass) {
  const TetMesh mesh = jittered_box(5, 3, 3, 0.2, 11);
  for (const StrainMeasure strain : {StrainMeasure::GreenLagrange, StrainMeasure::Cauchy}) {
    MaterialLaw law = law_with(5e5, 3e4, 0.7, 20);
    law.strain = strain;
    law.scales = kScales;
    const LevelModel plain = build_level_model(mesh, law);
    const TetTensors q = random_tensors(plain.num_tets(), 12);
    law.tet_tensors = std::make_shared<const TetTensors>(q);
    const LevelModel scaled = build_level_model(mesh, law);
    ASSERT_EQ(scaled.mass, plain.mass);
    ASSERT_EQ(scaled.laplacian_w, plain.laplacian_w);
    ASSERT_EQ(scaled.geo.volume, plain.geo.volume);
    for (int t = 0; t < plain.num_tets(); t += 7) {  // each bound: the tet's tensor's
      MaterialLaw own = law;
      own.tet_tensors = nullptr;
      own.scales = kScales.times(q[t]);
      const TetEnergyBounds b = tet_energy_bounds(plain.geo, own);
      EXPECT_EQ(scaled.bounds.stiffness[t], b.stiffness[t]) << t;
      EXPECT_EQ(scaled.bounds.damping[t], b.damping[t]) << t;
    }
    const BothForces f = forces_of_both(plain, scaled, 13);
    const std::vector<Vec3>&u = f.u, &v = f.v, &f_plain = f.a, &f_scaled = f.b;
    // Direct sum of each tet's stress under its own tensor, per point.
    double scale = 0, err = 0;
    for (int i = 0; i < plain.num_points(); ++i) {
      Vec3 expected = Vec3::Zero();
      for (int s = plain.adj.inc_start[i]; s < plain.adj.inc_start[i + 1]; ++s) {
        const int t = plain.adj.inc_tet[s];
        const StiffnessScales own = kScales.times(q[t]);
        const Mat3 G = tet_gradient(plain.geo.grad[t], plain.geo.tets[t], u.data());
        const Mat3 Gd = tet_gradient(plain.geo.grad[t], plain.geo.tets[t], v.data());
        const Mat3 P = strain == StrainMeasure::GreenLagrange ? green_piola(G, &Gd, law, own)
                                                               : cauchy_stress(G, &Gd, law, own);
        expected -= plain.geo.volume[t] * (P * plain.geo.grad[t][plain.adj.inc_local[s]]);
      }
      scale = std::max(scale, expected.norm());
      err = std::max(err, (expected - f_scaled[i]).norm());
    }
    EXPECT_LT(err, 1e-11 * scale) << (strain == StrainMeasure::Cauchy ? "Cauchy" : "Green");
    double moved = 0;
    for (int i = 0; i < plain.num_points(); ++i) moved = std::max(moved, (f_scaled[i] - f_plain[i]).norm());
    EXPECT_GT(moved, 0.1 * scale);  // the factors did change the forces
  }
}

// Factors of one on every tet are the level's own law: the Green–Lagrange kernel's per-tet form
// applies a tet's scales as the level's are applied, so the forces keep their bits.
TEST(CalibratedLaw, PerTetTensorsOfOneKeepTheLevelsBits) {
  const TetMesh mesh = jittered_box(5, 3, 3, 0.2, 17);
  MaterialLaw law = law_with(5e5, 3e4, 0.7, 20);
  law.scales = kScales;
  const LevelModel plain = build_level_model(mesh, law);
  law.tet_tensors = std::make_shared<const TetTensors>(plain.num_tets(), ComponentValues{1, 1, 1, 1, 1, 1, 1});
  const LevelModel ones = build_level_model(mesh, law);
  const BothForces f = forces_of_both(plain, ones, 18);
  EXPECT_EQ(0, std::memcmp(f.a.data(), f.b.data(), f.a.size() * sizeof(Vec3)));
  EXPECT_EQ(plain.bounds.stiffness, ones.bounds.stiffness);
}

// The per-tet fit's pieces: K(s, q) assembled with the factors is Σ_t Σ_j s_j q_tj K_tj, whose
// per-tet bilinear terms sum to the parts, and the level's own linear force.
TEST(CalibratedLaw, ComponentStiffnessPerTetTermsSumToTheParts) {
  const TetMesh mesh = jittered_box(4, 3, 2, 0.2, 15);
  MaterialLaw law = law_with(4e5, 2e4);
  law.strain = StrainMeasure::Cauchy;
  std::vector<std::uint8_t> fixed(mesh.points.size(), 0);
  for (size_t i = 0; i < mesh.points.size(); ++i) fixed[i] = mesh.points[i].x() < 1e-9;
  const TetGeometry geo = build_tet_geometry(mesh);
  const int n = static_cast<int>(mesh.points.size());
  const ComponentStiffness cs = component_stiffness(geo, n, law, fixed);
  Eigen::VectorXd a = Eigen::VectorXd::Random(cs.free_dofs());
  Eigen::VectorXd b = Eigen::VectorXd::Random(cs.free_dofs());
  const std::vector<ComponentValues> terms = cs.tet_terms(a, b);
  for (int j = 0; j < 7; ++j) {
    double sum = 0;
    for (const ComponentValues& t : terms) sum += t[j];
    const double whole = a.dot(cs.parts[j] * b);
    EXPECT_NEAR(sum, whole, 1e-10 * std::abs(whole) + 1e-300) << "component " << j;
  }
  const TetTensors q = random_tensors(cs.num_tets(), 16);
  const std::array<double, 7> s = kScales.components();
  const SparseMatrix K = cs.combined(s, q);
  const TetTensors ones(cs.num_tets(), ComponentValues{1, 1, 1, 1, 1, 1, 1});
  EXPECT_LT((Eigen::MatrixXd(cs.combined(s, ones)) - Eigen::MatrixXd(cs.combined(s))).norm(),
            1e-12 * Eigen::MatrixXd(cs.combined(s)).norm());
  // Σ_t Σ_j s_j q_tj aᵀK_tj b from the terms is aᵀ K(s, q) b.
  double by_terms = 0;
  for (int t = 0; t < cs.num_tets(); ++t)
    for (int j = 0; j < 7; ++j) by_terms += s[j] * q[t][j] * terms[t][j];
  EXPECT_NEAR(by_terms, a.dot(K * b), 1e-10 * std::abs(by_terms));
  // ... and is the linear force of a level built with those factors.
  law.scales = kScales;
  law.tet_tensors = std::make_shared<const TetTensors>(q);
  const LevelModel m = build_level_model(mesh, law, false, fixed);
  std::vector<Vec3> u(n, Vec3::Zero()), v(n, Vec3::Zero()), f(n);
  for (int i = 0; i < n; ++i)
    if (cs.dof_of_point[i] >= 0) u[i] = a.segment<3>(cs.dof_of_point[i]) * 1e-3;
  ForceWorkspace ws;
  internal_forces(m, u.data(), v.data(), f.data(), ws);
  const Eigen::VectorXd Ka = K * (a * 1e-3);
  for (int i = 0; i < n; ++i) {
    if (cs.dof_of_point[i] < 0) continue;
    ASSERT_LT((Ka.segment<3>(cs.dof_of_point[i]) + f[i]).norm(), 1e-10 * Ka.norm()) << i;
  }
}

}  // namespace
}  // namespace mrsim
