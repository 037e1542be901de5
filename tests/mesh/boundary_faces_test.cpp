// The skin of a tet mesh: closed, outward, the box's area.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace mrsim
