// The skin of a tet mesh: closed, outward, the box's area.
#include <gtest/gtest.h>

#include <algorithm>

#include "mesh/box_mesh.hpp"
#include "mesh/boundary_faces.hpp"

namespace mrsim {
namespace {

TEST(BoundaryFaces, BoxSkinIsClosedOutwardAndHasTheBoxArea) {
  const TetMesh m = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.06, 0.04), 5, 3, 2);
  const auto faces = boundary_faces(m);
  EXPECT_EQ(faces.size(), 2u * 2 * (5 * 3 + 5 * 2 + 3 * 2));  // two triangles per cell face
  double area = 0, volume = 0;
  const Vec3 centre(0.05, 0.03, 0.02);
  for (const Face& f : faces) {
    const Vec3 &a = m.points[f[0]], &b = m.points[f[1]], &c = m.points[f[2]];
    const Vec3 n = 0.5 * (b - a).cross(c - a);
    area += n.norm();
    volume += a.dot(n) / 3.0;  // divergence theorem: only right if every normal points out
    EXPECT_GT(n.dot((a + b + c) / 3.0 - centre), 0.0);
  }
  EXPECT_NEAR(area, 2 * (0.1 * 0.06 + 0.1 * 0.04 + 0.06 * 0.04), 1e-12);
  EXPECT_NEAR(volume, 0.1 * 0.06 * 0.04, 1e-12);
}

// The contract the skin, loads and patch weights rely on: the faces met exactly once, each as
// its tet orients it, in the order of their sorted vertices, whatever the order of the tets.
// Checked against a plain reference on a mesh with holes and tets in shuffled order.
TEST(BoundaryFaces, SameListAndOrderAsSortingEveryFace) {
  TetMesh m = make_box_mesh(Vec3(0, 0, 0), Vec3(1, 0.6, 0.4), 7, 5, 3);
  std::vector<Tet> kept;
  for (std::size_t t = 0; t < m.tets.size(); ++t)
    if (t % 7 != 3) kept.push_back(m.tets[t]);  // holes: inner faces become boundary
  std::reverse(kept.begin(), kept.end());
  for (std::size_t t = 0; t < kept.size(); t += 2) std::swap(kept[t], kept[(t * 13) % kept.size()]);
  m.tets = kept;
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  std::vector<std::pair<Face, Face>> all;  // (sorted, oriented)
  for (const Tet& t : m.tets)
    for (const auto& f : kFaces) {
      const Face face{t[f[0]], t[f[1]], t[f[2]]};
      Face key = face;
      std::sort(key.begin(), key.end());
      all.push_back({key, face});
    }
  std::stable_sort(all.begin(), all.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Face> expected;
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i + 1;
    while (j < all.size() && all[j].first == all[i].first) ++j;
    if (j - i == 1) expected.push_back(all[i].second);
    i = j;
  }
  const std::vector<Face> got = boundary_faces(m);
  EXPECT_GT(got.size(), 2u * 2 * (7 * 5 + 7 * 3 + 5 * 3));  // more than the box's hull
  EXPECT_EQ(got, expected);
}

}  // namespace
}  // namespace mrsim
