// Structured box meshes (mesh/box_mesh.hpp), uniform and graded along x.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "mesh/box_mesh.hpp"

namespace mrsim {
namespace {

double total_volume(const TetMesh& m, double* smallest) {
  double v = 0;
  *smallest = 1e300;
  for (const Tet& t : m.tets) {
    const double vt = signed_volume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]);
    v += vt;
    *smallest = std::min(*smallest, vt);
  }
  return v;
}

TEST(GradedBoxMesh, CellsFollowTheWidthsAndFillTheBox) {
  const TetMesh m = make_graded_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), {1, 1, 0.25, 0.25, 0.5}, 2, 2);
  std::set<double> xs;
  for (const Vec3& p : m.points) xs.insert(p.x());
  const std::vector<double> got(xs.begin(), xs.end());
  const std::vector<double> want = {0, 0.1 / 3, 0.2 / 3, 0.2 / 3 + 0.025 / 3, 0.2 / 3 + 0.05 / 3, 0.1};
  ASSERT_EQ(got.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-15);
  double smallest = 0;
  EXPECT_NEAR(total_volume(m, &smallest), 0.1 * 0.02 * 0.02, 1e-18);
  EXPECT_GT(smallest, 0);
  EXPECT_EQ(m.tets.size(), 6u * 5 * 2 * 2);
  EXPECT_THROW(make_graded_box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), {1, 0}, 1, 1), std::invalid_argument);
}

TEST(GradedBoxMesh, EveryAxisFollowsItsWidths) {
  const TetMesh m = make_graded_box_mesh(Vec3(-1, -2, -3), Vec3(1, 2, 0), {2, 1, 1, 2}, {1, 3},
                                         {1, 1, 4});
  std::set<double> xs, ys, zs;
  for (const Vec3& p : m.points) {
    xs.insert(p.x());
    ys.insert(p.y());
    zs.insert(p.z());
  }
  auto expect_nodes = [](const std::set<double>& got, const std::vector<double>& want) {
    ASSERT_EQ(got.size(), want.size());
    size_t i = 0;
    for (double g : got) EXPECT_NEAR(g, want[i++], 1e-15);
  };
  expect_nodes(xs, {-1, -1.0 / 3, 0, 1.0 / 3, 1});
  expect_nodes(ys, {-2, -1, 2});
  expect_nodes(zs, {-3, -2.5, -2, 0});
  double smallest = 0;
  EXPECT_NEAR(total_volume(m, &smallest), 2.0 * 4.0 * 3.0, 1e-12);
  EXPECT_GT(smallest, 0);
}

}  // namespace
}  // namespace mrsim
