// Properties of the elastic and damping forces (method.md §2): patch test, rigid motions,
// consistency with the energy, linear limit of the Green model.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <random>

#include <Eigen/Geometry>

#include "core/parallel.hpp"
#include "mesh/box_mesh.hpp"
#include "physics/internal_force.hpp"
#include "physics/laplacian_criterion.hpp"

using namespace mrsim;

namespace {

MaterialLaw law(StrainMeasure s, double phi = 0, double psi = 0) {
  MaterialLaw l;
  l.strain = s;
  l.lambda = 5.0e5;
  l.mu = 2.0e5;
  l.phi = phi;
  l.psi = psi;
  l.density = 1000;
  return l;
}

// A box with its interior points jittered so no test passes by symmetry alone.
TetMesh jittered_box(int n = 4) {
  TetMesh m = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.08, 0.06), n, n, n);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(-0.15, 0.15);
  const Vec3 h(0.1 / n, 0.08 / n, 0.06 / n);
  for (Vec3& p : m.points) {
    const bool interior = p.x() > 1e-9 && p.x() < 0.1 - 1e-9 && p.y() > 1e-9 &&
                          p.y() < 0.08 - 1e-9 && p.z() > 1e-9 && p.z() < 0.06 - 1e-9;
    if (interior) p += Vec3(d(rng) * h.x(), d(rng) * h.y(), d(rng) * h.z());
  }
  return m;
}

bool on_boundary(const Vec3& p) {
  return p.x() < 1e-9 || p.x() > 0.1 - 1e-9 || p.y() < 1e-9 || p.y() > 0.08 - 1e-9 ||
         p.z() < 1e-9 || p.z() > 0.06 - 1e-9;
}

std::vector<Vec3> forces(const LevelModel& m, const std::vector<Vec3>& u,
                         const std::vector<Vec3>& v) {
  std::vector<Vec3> f(u.size());
  ForceWorkspace ws;
  internal_forces(m, u.data(), v.data(), f.data(), ws);
  return f;
}

Mat3 rotation(double angle, Vec3 axis) { return Eigen::AngleAxisd(angle, axis.normalized()).matrix(); }

double max_norm(const std::vector<Vec3>& f) {
  double x = 0;
  for (const Vec3& v : f) x = std::max(x, v.norm());
  return x;
}

// Force scale for relative tolerances: the force a 1e-3 strain would create on a point.
double force_scale(const LevelModel& m) { return (m.law.lambda + 2 * m.law.mu) * 1e-3 * 1e-4; }

class BothModels : public ::testing::TestWithParam<StrainMeasure> {};

// Displacements of about 2 % of the box and velocities of order one, from `seed`.
void random_state(const TetMesh& mesh, unsigned seed, std::vector<Vec3>& u, std::vector<Vec3>& v) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1, 1);
  u.resize(mesh.points.size());
  v.resize(mesh.points.size());
  for (auto& x : u) x = 2e-2 * Vec3(d(rng), d(rng), d(rng));
  for (auto& x : v) x = Vec3(d(rng), d(rng), d(rng));
}

}  // namespace

TEST_P(BothModels, PatchTestLinearFieldGivesZeroInteriorForce) {
  const TetMesh mesh = jittered_box();
  const LevelModel m = build_level_model(mesh, law(GetParam()));
  Mat3 A;
  A << 1e-3, 2e-4, -3e-4, 5e-4, -2e-3, 1e-4, -4e-4, 3e-4, 1.5e-3;
  std::vector<Vec3> u(mesh.points.size()), v(mesh.points.size(), Vec3::Zero());
  for (size_t i = 0; i < u.size(); ++i) u[i] = A * mesh.points[i] + Vec3(1e-3, 0, -2e-3);
  const auto f = forces(m, u, v);
  double interior = 0, boundary = 0;
  for (size_t i = 0; i < u.size(); ++i)
    (on_boundary(mesh.points[i]) ? boundary : interior) =
        std::max(on_boundary(mesh.points[i]) ? boundary : interior, f[i].norm());
  EXPECT_LT(interior, 1e-10 * force_scale(m));
  EXPECT_GT(boundary, 1e-2 * force_scale(m));  // the traction is real: the test can fail
}

TEST_P(BothModels, RigidTranslationGivesZeroForceAndEnergy) {
  const TetMesh mesh = jittered_box();
  const LevelModel m = build_level_model(mesh, law(GetParam(), 10, 20));
  std::vector<Vec3> u(mesh.points.size(), Vec3(0.3, -0.2, 0.7));
  std::vector<Vec3> v(mesh.points.size(), Vec3(1, 2, 3));
  // Round-off only: Σ_a ∇N_a = 0 holds to the last bit only for the Cauchy edge form.
  EXPECT_LT(max_norm(forces(m, u, v)), 1e-9 * force_scale(m));
  EXPECT_LT(elastic_energy(m, u.data()), 1e-20);
}

TEST_P(BothModels, LaplacianCriterionVanishesForLinearFieldsEverywhere) {
  const TetMesh mesh = jittered_box();
  const LevelModel m = build_level_model(mesh, law(GetParam()));
  const Mat3 R = rotation(0.8, Vec3(1, 2, 3));
  std::vector<Vec3> u(mesh.points.size());
  for (size_t i = 0; i < u.size(); ++i) u[i] = (R - Mat3::Identity()) * mesh.points[i];
  std::vector<double> c;
  laplacian_criterion(m, u.data(), c);
  for (double x : c) EXPECT_LT(x, 1e-12);
  // A quadratic field has a non-zero Laplacian, 2 per unit of x² coefficient.
  for (size_t i = 0; i < u.size(); ++i) u[i] = Vec3(mesh.points[i].x() * mesh.points[i].x(), 0, 0);
  for (size_t i = 0; i < u.size(); ++i)
    if (!on_boundary(mesh.points[i])) {
      EXPECT_NEAR(corrected_laplacian(m, static_cast<int>(i), u.data()).x(), 2.0, 0.6);
    }
}

INSTANTIATE_TEST_SUITE_P(Strain, BothModels,
                         ::testing::Values(StrainMeasure::Cauchy, StrainMeasure::GreenLagrange));

TEST(GreenForce, LargeRigidRotationGivesZeroForceAndEnergy) {
  const TetMesh mesh = jittered_box();
  const LevelModel m = build_level_model(mesh, law(StrainMeasure::GreenLagrange, 10, 20));
  const Mat3 R = rotation(1.2, Vec3(1, -2, 0.5));
  const Vec3 omega(0.4, -1, 2);
  std::vector<Vec3> u(mesh.points.size()), v(mesh.points.size());
  for (size_t i = 0; i < u.size(); ++i) {
    u[i] = (R - Mat3::Identity()) * mesh.points[i] + Vec3(0.01, 0, 0);
    v[i] = omega.cross(R * mesh.points[i]);  // rigid velocity field: no strain rate
  }
  EXPECT_LT(max_norm(forces(m, u, v)), 1e-9 * force_scale(m));
  EXPECT_LT(elastic_energy(m, u.data()), 1e-18);
}

TEST(CauchyForce, LargeRotationProducesSpuriousForce) {
  // The linear strain is not rotation invariant (method.md §1): a rigid rotation by 60° looks
  // like a compression of (cos θ - 1) ≈ -50 % and creates large forces and energy.
  const TetMesh mesh = jittered_box();
  const LevelModel m = build_level_model(mesh, law(StrainMeasure::Cauchy));
  const Mat3 R = rotation(M_PI / 3, Vec3(0, 0, 1));
  std::vector<Vec3> u(mesh.points.size()), v(mesh.points.size(), Vec3::Zero());
  for (size_t i = 0; i < u.size(); ++i) u[i] = (R - Mat3::Identity()) * mesh.points[i];
  EXPECT_GT(max_norm(forces(m, u, v)), 100 * force_scale(m));
  // Energy of ε = (cos θ - 1) in the x-y plane: V [λ/2 (2c)² + μ 2c²], c = cos θ - 1.
  const double c = std::cos(M_PI / 3) - 1, V = 0.1 * 0.08 * 0.06;
  const double expected = V * (0.5 * m.law.lambda * 4 * c * c + m.law.mu * 2 * c * c);
  EXPECT_NEAR(elastic_energy(m, u.data()), expected, 1e-9 * expected);
}

TEST(GreenForce, MatchesFiniteDifferenceOfEnergy) {
  const TetMesh mesh = jittered_box(3);
  const LevelModel m = build_level_model(mesh, law(StrainMeasure::GreenLagrange));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(-1, 1);
  std::vector<Vec3> u(mesh.points.size()), v(mesh.points.size(), Vec3::Zero());
  for (auto& x : u) x = 4e-3 * Vec3(d(rng), d(rng), d(rng));  // strains of order 10 %
  const auto f = forces(m, u, v);
  const double h = 1e-8;
  double worst = 0;
  for (int i = 0; i < static_cast<int>(u.size()); i += 7)
    for (int k = 0; k < 3; ++k) {
      auto up = u, um = u;
      up[i][k] += h;
      um[i][k] -= h;
      const double dE = (elastic_energy(m, up.data()) - elastic_energy(m, um.data())) / (2 * h);
      worst = std::max(worst, std::abs(-dE - f[i][k]) / (std::abs(f[i][k]) + force_scale(m)));
    }
  EXPECT_LT(worst, 1e-5);
}

TEST(GreenForce, SmallStrainLimitIsTheCauchyForce) {
  const TetMesh mesh = jittered_box(3);
  const LevelModel g = build_level_model(mesh, law(StrainMeasure::GreenLagrange, 3, 7));
  const LevelModel c = build_level_model(mesh, law(StrainMeasure::Cauchy, 3, 7));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-1, 1);
  std::vector<Vec3> u(mesh.points.size()), v(mesh.points.size());
  for (auto& x : u) x = 1e-9 * Vec3(d(rng), d(rng), d(rng));
  for (auto& x : v) x = 1e-2 * Vec3(d(rng), d(rng), d(rng));
  const auto fg = forces(g, u, v), fc = forces(c, u, v);
  for (size_t i = 0; i < u.size(); ++i)
    EXPECT_LT((fg[i] - fc[i]).norm(), 1e-6 * (fc[i].norm() + 1e-12)) << i;
}

TEST(CauchyForce, EdgeGatherEqualsPerTetAssembly) {
  const TetMesh mesh = jittered_box(3);
  const LevelModel m = build_level_model(mesh, law(StrainMeasure::Cauchy, 3, 7));
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> d(-1, 1);
  std::vector<Vec3> u(mesh.points.size()), v(mesh.points.size());
  for (auto& x : u) x = 1e-3 * Vec3(d(rng), d(rng), d(rng));
  for (auto& x : v) x = Vec3(d(rng), d(rng), d(rng));
  const auto f = forces(m, u, v);
  for (int i = 0; i < m.num_points(); ++i) {
    const Vec3 ref = point_internal_force(m, i, u.data(), v.data());
    EXPECT_LT((f[i] - ref).norm(), 1e-9 * (ref.norm() + force_scale(m))) << i;
  }
}

TEST(Damping, RigidRotationRateIsNotDamped) {
  // ∇v skew-symmetric ⇒ ε̇ = Ė = 0 (method.md §1): no damping force, both models.
  const TetMesh mesh = jittered_box();
  for (StrainMeasure s : {StrainMeasure::Cauchy, StrainMeasure::GreenLagrange}) {
    MaterialLaw l = law(s, 50, 80);
    l.lambda = l.mu = 0;  // damping only
    const LevelModel m = build_level_model(mesh, l);
    const Vec3 omega(1, -2, 3);
    std::vector<Vec3> u(mesh.points.size(), Vec3::Zero()), v(mesh.points.size());
    for (size_t i = 0; i < u.size(); ++i) v[i] = omega.cross(mesh.points[i]);
    EXPECT_LT(max_norm(forces(m, u, v)), 1e-12);
    // A shearing velocity is damped.
    for (size_t i = 0; i < u.size(); ++i) v[i] = Vec3(mesh.points[i].z(), 0, 0);
    EXPECT_GT(max_norm(forces(m, u, v)), 1e-6);
  }
}

// The tet pass on one thread adds each tet's forces to its vertices at once; on two, Green–
// Lagrange splits the points into id ranges, each thread passing the tets that touch its range,
// and Cauchy stores per-tet forces that each point gathers. Over the ascending tet lists the
// hierarchy passes, all add a point's terms in the same order: the same bits, for a subset of
// the points, with tet weights (the energy coupling's shares, some zero) and without, for both
// strain measures. Points outside the set are left as they were.
TEST(TetPass, OneAndTwoThreadsGiveTheSameBits) {
  const TetMesh mesh = jittered_box(4);
  std::vector<Vec3> u, v;
  random_state(mesh, 11, u, v);
  const int saved = parallel_threshold(), saved_threads = omp_get_max_threads();
  for (StrainMeasure s : {StrainMeasure::Cauchy, StrainMeasure::GreenLagrange}) {
    const LevelModel m = build_level_model(mesh, law(s, 3, 7));
    std::vector<int> points, tets;
    for (int i = 0; i < m.num_points(); i += 3) points.push_back(i);
    std::vector<unsigned char> mark(m.num_tets(), 0);
    live_tets(m, IndexSet::of(points), mark, tets);
    std::vector<double> weight(m.num_tets(), 0.0);
    for (size_t k = 0; k < tets.size(); ++k) weight[tets[k]] = (k % 4) * 0.25;  // some zero
    const Vec3 untouched(7, 7, 7);
    for (bool weighted : {false, true}) {
      std::vector<Vec3> f[2];
      for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        set_parallel_threshold(1);
        ForceWorkspace ws;
        std::vector<Vec3>& out = f[threads - 1];
        out.assign(u.size(), untouched);
        if (weighted)
          weighted_internal_forces(m, IndexSet::of(points), IndexSet::of(tets), weight.data(),
                                   u.data(), v.data(), out.data(), ws);
        else if (s == StrainMeasure::GreenLagrange)  // Cauchy's plain path is the edge gather
          internal_forces(m, IndexSet::of(points), IndexSet::of(tets), u.data(), v.data(),
                          out.data(), ws);
        else
          weighted_internal_forces(m, IndexSet::of(points), IndexSet::of(tets), nullptr,
                                   u.data(), v.data(), out.data(), ws);
      }
      // Points in any order (the threads' ranges need them ascending, or the stored pass).
      std::vector<int> reversed(points.rbegin(), points.rend());
      std::vector<Vec3> any_order(u.size(), untouched);
      {
        omp_set_num_threads(2);
        set_parallel_threshold(1);
        ForceWorkspace ws;
        weighted_internal_forces(m, IndexSet::of(reversed), IndexSet::of(tets),
                                 weighted ? weight.data() : nullptr, u.data(), v.data(),
                                 any_order.data(), ws);
      }
      set_parallel_threshold(saved);
      EXPECT_EQ(std::memcmp(f[0].data(), f[1].data(), f[0].size() * sizeof(Vec3)), 0)
          << (weighted ? "weighted " : "") << (s == StrainMeasure::Cauchy ? "Cauchy" : "Green");
      EXPECT_EQ(std::memcmp(f[0].data(), any_order.data(), f[0].size() * sizeof(Vec3)), 0)
          << "points in descending order";
      int moved = 0;
      for (int i = 0; i < m.num_points(); ++i) {
        const bool in_set = i % 3 == 0;
        if (!in_set) {
          EXPECT_EQ(f[0][i], untouched) << i;
        }
        if (in_set && !weighted) {
          const Vec3 ref = point_internal_force(m, i, u.data(), v.data());
          EXPECT_LT((f[0][i] - ref).norm(), 1e-9 * (ref.norm() + force_scale(m))) << i;
        }
        moved += in_set && f[0][i].norm() > 0;
      }
      EXPECT_GT(moved, m.num_points() / 4);
    }
  }
  omp_set_num_threads(saved_threads);
}

// A packed list said to be closed (a coupled level's live tets, whose every vertex is an active
// point or a ghost: invariant I2) is passed without the points' mask, with the same bits where
// the points cover the tets; an open one keeps the mask, and the points outside the set keep
// their values. The closed flag is a promise the caller keeps: broken here on purpose, the
// vertices outside the set receive forces, which shows the mask really is skipped.
TEST(TetPass, ClosedPackedListSkipsTheMaskWithTheSameBits) {
  const TetMesh mesh = jittered_box(4);
  std::vector<Vec3> u, v;
  random_state(mesh, 5, u, v);
  const LevelModel m = build_level_model(mesh, law(StrainMeasure::GreenLagrange, 3, 7));
  std::vector<int> seeds, tets, covered;
  for (int i = 0; i < m.num_points(); i += 5) seeds.push_back(i);
  std::vector<unsigned char> mark(m.num_tets(), 0);
  live_tets(m, IndexSet::of(seeds), mark, tets);
  std::vector<unsigned char> in(m.num_points(), 0);
  for (int t : tets)
    for (int p : m.geo.tets[t]) in[p] = 1;
  for (int i = 0; i < m.num_points(); ++i)
    if (in[i]) covered.push_back(i);
  ASSERT_LT(covered.size(), static_cast<size_t>(m.num_points()));
  std::vector<double> weight(m.num_tets(), 0.0);
  for (size_t k = 0; k < tets.size(); ++k) weight[tets[k]] = 0.25 + (k % 3) * 0.25;
  const Vec3 untouched(7, 7, 7);
  const int saved_threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto pass = [&](const std::vector<int>& points, bool closed) {
    ForceWorkspace ws;
    ws.packed.pack(m.geo, tets, closed);
    std::vector<Vec3> f(u.size(), untouched);
    weighted_internal_forces(m, IndexSet::of(points), IndexSet::of(tets), weight.data(),
                             u.data(), v.data(), f.data(), ws);
    return f;
  };
  const std::vector<Vec3> open = pass(covered, false), closed = pass(covered, true);
  EXPECT_EQ(std::memcmp(open.data(), closed.data(), open.size() * sizeof(Vec3)), 0);
  int outside = 0;
  for (int i = 0; i < m.num_points(); ++i) outside += !in[i] && open[i] == untouched;
  EXPECT_EQ(outside, m.num_points() - static_cast<int>(covered.size()));
  // The seeds alone do not cover their tets: masked, only the seeds move; unmasked, the
  // other vertices of the tets receive forces too.
  const std::vector<Vec3> masked = pass(seeds, false), unmasked = pass(seeds, true);
  int masked_others = 0, unmasked_others = 0;
  for (int i = 0; i < m.num_points(); ++i)
    if (in[i] && i % 5 != 0) {
      masked_others += masked[i] != untouched;
      unmasked_others += unmasked[i] != untouched;
    }
  EXPECT_EQ(masked_others, 0);
  EXPECT_GT(unmasked_others, 0);
  omp_set_num_threads(saved_threads);
}
