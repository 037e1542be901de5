// Static links between levels (hierarchy/level_links.hpp): the count of points a level shares
// with the coarser one, which run.cpp warns about for the energy couplings.
#include <gtest/gtest.h>

#include "hierarchy/hierarchy_fixture.hpp"
#include "physics/point_adjacency.hpp"

namespace mrsim {
namespace {

std::vector<LevelLinks> links_of(const std::vector<TetMesh>& meshes,
                                 std::vector<PointAdjacency>& adj) {
  std::vector<HierarchyLevel> levels;
  adj.clear();
  for (const TetMesh& m : meshes)
    adj.push_back(build_point_adjacency(static_cast<int>(m.points.size()), m.tets));
  for (size_t l = 0; l < meshes.size(); ++l) levels.push_back({&meshes[l], &adj[l]});
  return build_level_links(levels);
}

TEST(LevelLinks, NestedMeshesShareEveryCoarsePointIndependentOnesOnlyCorners) {
  const Vec3 lo(0, 0, 0), hi(0.1, 0.06, 0.04);
  std::vector<PointAdjacency> adj;
  const std::vector<TetMesh> nested = {make_box_mesh(lo, hi, 4, 2, 2), make_box_mesh(lo, hi, 8, 4, 4)};
  const auto nested_links = links_of(nested, adj);
  EXPECT_EQ(coincident_with_parent(nested_links[1]), 5 * 3 * 3);  // every level-0 grid point
  const auto jittered = testing::jittered_box_levels({{4, 3, 2}, {9, 5, 5}}, 3, 0.15);
  const auto independent_links = links_of(jittered, adj);
  EXPECT_LE(coincident_with_parent(independent_links[1]), 8);  // the box's corners at most
}

}  // namespace
}  // namespace mrsim
