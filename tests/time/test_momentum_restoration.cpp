// The rigid motion that the momentum-restoring semi-implicit step keeps out of the filter
// (time/momentum_restoration.hpp).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>
#include <vector>

#include "time/momentum_restoration.hpp"

namespace mrsim {
namespace {

struct Cloud {
  std::vector<Vec3> rest;
  PointState state;
};

// Random points of random masses, displaced so that x = R (X − C) + C + t + wobble.
Cloud turned_cloud(const Mat3& R, const Vec3& t, double wobble) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-1, 1);
  Cloud c;
  const int n = 40;
  c.state.resize(n);
  Vec3 centre = Vec3::Zero();
  double mass = 0;
  for (int i = 0; i < n; ++i) {
    c.rest.push_back(Vec3(0.1 * d(rng), 0.03 * d(rng), 0.02 * d(rng)));
    c.state.inv_mass[i] = 1 / (1.0 + 0.5 * d(rng));
    mass += 1 / c.state.inv_mass[i];
    centre += c.rest.back() / c.state.inv_mass[i];
  }
  centre /= mass;
  for (int i = 0; i < n; ++i) {
    const Vec3 x = R * (c.rest[i] - centre) + centre + t +
                   wobble * Vec3(d(rng), d(rng), d(rng));
    c.state.u[i] = x - c.rest[i];
  }
  return c;
}

TEST(MomentumRestoration, BodyRotationIsTheTurnOfTheRestShape) {
  const Mat3 R = Eigen::AngleAxisd(1.3, Vec3(0.2, -0.5, 0.8).normalized()).toRotationMatrix();
  const Vec3 t(0.4, -0.1, 2.0);
  for (double wobble : {0.0, 1e-3}) {
    Cloud c = turned_cloud(R, t, wobble);
    const MomentumSums sums = momentum_sums({{&c.state, c.rest.data(), IndexSet::all(40)}});
    const Mat3 found = body_rotation(sums);
    EXPECT_NEAR((found.transpose() * found - Mat3::Identity()).norm(), 0, 1e-12);
    EXPECT_NEAR(found.determinant(), 1, 1e-12);
    // Exact for a rigid motion; a small deformation moves it by about its size over the body's.
    EXPECT_LT((found - R).norm(), wobble == 0 ? 1e-12 : 0.05) << wobble;
  }
  // At rest, and for a body with no mass, the identity.
  Cloud rest = turned_cloud(Mat3::Identity(), Vec3::Zero(), 0.0);
  EXPECT_LT((body_rotation(momentum_sums({{&rest.state, rest.rest.data(), IndexSet::all(40)}})) -
             Mat3::Identity())
                .norm(),
            1e-12);
  EXPECT_EQ(body_rotation(MomentumSums{}), Mat3::Identity());
}

TEST(MomentumRestoration, RotatingVelocitiesThereAndBackIsTheIdentityOnFreePoints) {
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  Cloud c = turned_cloud(R, Vec3::Zero(), 0.0);
  for (int i = 0; i < 40; ++i) c.state.v[i] = Vec3(i, -i, 0.5 * i);
  c.state.free_point[3] = 0;
  const std::vector<Vec3> v0 = c.state.v;
  const std::vector<MomentumBlock> blocks{{&c.state, c.rest.data(), IndexSet::all(40)}};
  std::vector<PointState*> states{&c.state};
  rotate_velocities(blocks, R, states);
  EXPECT_EQ(c.state.v[3], v0[3]);  // a held point is left alone
  EXPECT_LT((c.state.v[5] - R * v0[5]).norm(), 1e-12);
  rotate_velocities(blocks, R.transpose(), states);
  for (int i = 0; i < 40; ++i) EXPECT_LT((c.state.v[i] - v0[i]).norm(), 1e-12 * (1 + i));
}

}  // namespace
}  // namespace mrsim
