// corrected_laplacian keeps the gradients of a point's first tets for its second pass and
// computes those of any further tets again (physics/laplacian_criterion.cpp): both ways must give
// the value of the plain two-pass sum, to the bit, around a point with more tets than it keeps.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

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

}  // namespace
}  // namespace mrsim
