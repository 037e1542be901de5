// corrected_laplacian keeps the gradients of a point's first tets for its second pass and
// computes those of any further tets again (physics/laplacian_criterion.cpp): both ways must give
// the value of the plain two-pass sum, to the bit, around a point with more tets than it keeps.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/index_set.hpp"
#include "physics/internal_force.hpp"
#include "physics/laplacian_criterion.hpp"
#include "physics/level_model.hpp"

namespace mrsim {
namespace {

// A double cone around the origin: `n` points on the unit circle, an apex above and below, and
// 2n tets sharing the centre (point 0).
TetMesh double_fan(int n) {
  TetMesh m;
  m.points.push_back(Vec3::Zero());
  m.points.push_back(Vec3(0, 0, 1));
  m.points.push_back(Vec3(0, 0, -1.2));
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    m.points.push_back(Vec3(std::cos(a), std::sin(a) * 1.1, 0.05 * std::sin(3 * a)));
  }
  for (int k = 0; k < n; ++k) {
    const int r0 = 3 + k, r1 = 3 + (k + 1) % n;
    for (Tet t : {Tet{0, r0, r1, 1}, Tet{0, r1, r0, 2}}) {
      const auto& p = m.points;
      if (signed_volume(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) < 0) std::swap(t[2], t[3]);
      m.tets.push_back(t);
    }
  }
  return m;
}

// The two passes as method.md §3.1 writes them, each tet's gradient computed where it is used.
Vec3 two_pass_laplacian(const LevelModel& m, int i, const Vec3* u) {
  Mat3 mean = Mat3::Zero();
  double volume = 0;
  for (int s = m.adj.inc_start[i]; s < m.adj.inc_start[i + 1]; ++s) {
    const int t = m.adj.inc_tet[s];
    mean += m.geo.volume[t] * tet_gradient(m.geo.grad[t], m.geo.tets[t], u);
    volume += m.geo.volume[t];
  }
  mean /= volume;
  Vec3 L = Vec3::Zero();
  for (int s = m.adj.inc_start[i]; s < m.adj.inc_start[i + 1]; ++s) {
    const int t = m.adj.inc_tet[s];
    const Mat3 G = tet_gradient(m.geo.grad[t], m.geo.tets[t], u);
    L -= m.geo.volume[t] * ((G - mean) * m.geo.grad[t][m.adj.inc_local[s]]);
  }
  return L / m.lumped_volume[i];
}

TEST(CorrectedLaplacian, SameBitsAsTheTwoPassSumAroundAPointOfManyTets) {
  MaterialLaw law;
  law.lambda = 5.0e5;
  law.mu = 2.0e5;
  law.density = 1000;
  for (const int n : {10, 40}) {  // the centre in 20 tets, then in 80
    const TetMesh mesh = double_fan(n);
    const LevelModel m = build_level_model(mesh, law);
    ASSERT_EQ(m.adj.inc_start[1] - m.adj.inc_start[0], 2 * n);
    std::vector<Vec3> u(mesh.points.size());
    for (std::size_t p = 0; p < u.size(); ++p) {
      const Vec3& x = mesh.points[p];
      u[p] = Vec3(0.01 * x.x() * x.y() + 0.003 * x.z() * x.z(), 0.02 * x.y() * x.y(),
                  -0.01 * x.x() * x.z());
    }
    const Vec3 got = corrected_laplacian(m, 0, u.data());
    const Vec3 want = two_pass_laplacian(m, 0, u.data());
    ASSERT_GT(want.norm(), 0.0);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(got[c], want[c]) << n << " around, component " << c;
  }
}

// The criterion of a level's active points with each live tet's gradient computed once (what
// SpaceAdaptivity::evaluate() runs): the bits of corrected_laplacian() point by point, around
// the fan's centre (80 tets, more than it keeps) and at rim points; a tet left out of the list
// is an error, not a read of another tet's gradient.
TEST(CorrectedLaplacian, TheCriterionWithSharedGradientsHasThePointwiseBits) {
  MaterialLaw law;
  law.lambda = 5.0e5;
  law.mu = 2.0e5;
  law.density = 1000;
  const TetMesh mesh = double_fan(40);
  const LevelModel m = build_level_model(mesh, law);
  std::vector<Vec3> u(mesh.points.size());
  for (std::size_t p = 0; p < u.size(); ++p) {
    const Vec3& x = mesh.points[p];
    u[p] = Vec3(0.01 * x.x() * x.y() + 0.003 * x.z() * x.z(), 0.02 * x.y() * x.y(),
                -0.01 * x.x() * x.z());
  }
  const std::vector<int> points = {0, 4, 9, 17, 30};
  std::vector<unsigned char> mark(m.num_tets(), 0);
  std::vector<int> tets;
  live_tets(m, IndexSet::of(points), mark, tets);
  TetGradientCache cache;
  std::vector<double> got(mesh.points.size(), -1.0);
  corrected_criterion(m, points, tets, u.data(), cache, got.data());
  for (int p : points) {
    const double want = m.mean_edge[p] * corrected_laplacian(m, p, u.data()).norm();
    ASSERT_GT(want, 0.0);
    EXPECT_EQ(got[p], want) << "point " << p;
  }
  EXPECT_EQ(got[5], -1.0);  // not asked for
  for (int slot : cache.slot) EXPECT_EQ(slot, -1);  // left clean for the next level
  tets.erase(tets.begin() + 3);
  EXPECT_THROW(corrected_criterion(m, points, tets, u.data(), cache, got.data()),
               std::logic_error);
  for (int slot : cache.slot) EXPECT_EQ(slot, -1);  // and after the error
}

}  // namespace
}  // namespace mrsim
