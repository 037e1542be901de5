// The skin (contact/skin.hpp): a boundary skin keeps, for each vertex, the mesh point it is, so
// that the set-up's contact bound puts a vertex's penalty on that point without a search
// (simulation/stable_step.cpp); a given surface has no such point.
#include <gtest/gtest.h>

#include <set>

#include "../hierarchy/hierarchy_fixture.hpp"
#include "contact/skin.hpp"
#include "mesh/boundary_faces.hpp"

namespace mrsim {
namespace {

TEST(BoundarySkin, EachVertexIsTheMeshPointItNamesAndEveryBoundaryPointIsOne) {
  const testing::ThreeLevels f;
  for (const TetMesh& mesh : f.meshes) {
    const Skin skin = boundary_skin(mesh);
    ASSERT_EQ(skin.point.size(), skin.rest.size());
    std::set<int> boundary;
    for (const Face& face : boundary_faces(mesh))
      for (int v : face) boundary.insert(v);
    EXPECT_EQ(std::set<int>(skin.point.begin(), skin.point.end()), boundary);
    for (std::size_t s = 0; s < skin.rest.size(); ++s) {
      EXPECT_EQ(skin.rest[s], mesh.points[skin.point[s]]) << "skin vertex " << s;
      if (s > 0) {
        EXPECT_LT(skin.point[s - 1], skin.point[s]);  // renumbered in increasing order
      }
    }
  }
}

TEST(SurfaceSkin, AGivenSurfaceNamesNoMeshPoint) {
  const Skin skin = surface_skin({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {{0, 1, 2}});
  EXPECT_TRUE(skin.point.empty());
  EXPECT_EQ(skin.rest.size(), 3u);
}

}  // namespace
}  // namespace mrsim
