#include <gtest/gtest.h>

#include <random>

#include "mesh/box_mesh.hpp"
#include "physics/tet_geometry.hpp"

using namespace mrsim;

TEST(TetGeometry, ReferenceTetVolumeAndGradients) {
  TetMesh m;
  m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.tets = {{0, 1, 2, 3}};
  const TetGeometry g = build_tet_geometry(m);
  EXPECT_DOUBLE_EQ(g.volume[0], 1.0 / 6.0);
  EXPECT_TRUE(g.grad[0][0].isApprox(Vec3(-1, -1, -1)));
  EXPECT_TRUE(g.grad[0][1].isApprox(Vec3(1, 0, 0)));
  EXPECT_TRUE(g.grad[0][2].isApprox(Vec3(0, 1, 0)));
  EXPECT_TRUE(g.grad[0][3].isApprox(Vec3(0, 0, 1)));
}

TEST(TetGeometry, GradientsReproduceLinearFieldsOnDistortedTets) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-1, 1);
  for (int trial = 0; trial < 100; ++trial) {
    TetMesh m;
    for (int k = 0; k < 4; ++k) m.points.emplace_back(d(rng), d(rng), d(rng));
    m.tets = {{0, 1, 2, 3}};
    if (signed_volume(m.points[0], m.points[1], m.points[2], m.points[3]) < 1e-3) continue;
    const TetGeometry g = build_tet_geometry(m);
    Mat3 A;
    A << d(rng), d(rng), d(rng), d(rng), d(rng), d(rng), d(rng), d(rng), d(rng);
    Vec3 u[4];
    for (int k = 0; k < 4; ++k) u[k] = A * m.points[k] + Vec3(1, 2, 3);
    EXPECT_TRUE(tet_gradient(g.grad[0], m.tets[0], u).isApprox(A, 1e-10));
    EXPECT_NEAR((g.grad[0][0] + g.grad[0][1] + g.grad[0][2] + g.grad[0][3]).norm(), 0, 1e-12);
  }
}

TEST(TetGeometry, VolumesSumToBoxVolume) {
  const TetMesh m = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.03), 7, 3, 4);
  const TetGeometry g = build_tet_geometry(m);
  double v = 0;
  for (double x : g.volume) v += x;
  EXPECT_NEAR(v, 0.1 * 0.02 * 0.03, 1e-15);
}

TEST(TetGeometry, RejectsInvertedTet) {
  TetMesh m;
  m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.tets = {{0, 2, 1, 3}};
  EXPECT_THROW(build_tet_geometry(m), std::invalid_argument);
}
