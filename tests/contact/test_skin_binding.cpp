// bind_skin (contact/skin_binding.hpp): a boundary skin of the finest level takes its binding in
// the level below from the level links' parent tets, which located the same points with the
// same locator. It must be the binding that locating again gives, bit for bit, vertices outside
// the coarser mesh included; and a skin whose vertices are not the finest points exactly must be
// located again.
#include <gtest/gtest.h>

#include "../hierarchy/hierarchy_fixture.hpp"
#include "contact/skin.hpp"
#include "contact/skin_binding.hpp"
#include "hierarchy/level_links.hpp"
#include "hierarchy/tet_locator.hpp"
#include "physics/point_adjacency.hpp"

namespace mrsim {
namespace {

// Three box levels, the finest grown by 3 % about the centre, so that part of its boundary lies
// outside the coarser meshes (independent meshes of one object do not share their boundary).
struct GrownFinest {
  std::vector<TetMesh> meshes = testing::jittered_box_levels({{3, 2, 2}, {5, 3, 3}, {9, 6, 4}}, 5, 0.2);
  std::vector<PointAdjacency> adj;
  std::vector<TetLocator> locators;
  std::vector<LevelLinks> links;
  GrownFinest() {
    const Vec3 centre(0.05, 0.03, 0.02);
    for (Vec3& p : meshes.back().points) p = centre + 1.03 * (p - centre);
    std::vector<HierarchyLevel> levels;
    for (const TetMesh& m : meshes)
      adj.push_back(build_point_adjacency(static_cast<int>(m.points.size()), m.tets));
    for (std::size_t l = 0; l < meshes.size(); ++l) levels.push_back({&meshes[l], &adj[l]});
    for (const TetMesh& m : meshes) locators.emplace_back(m);
    links = build_level_links(levels, locators);
  }
};

void expect_same(const SkinBinding& a, const SkinBinding& b) {
  ASSERT_EQ(a.tet.size(), b.tet.size());
  for (std::size_t l = 0; l < a.tet.size(); ++l) {
    EXPECT_EQ(a.tet[l], b.tet[l]) << "level " << l;
    ASSERT_EQ(a.bary[l].size(), b.bary[l].size());
    for (std::size_t s = 0; s < a.bary[l].size(); ++s)
      EXPECT_EQ(a.bary[l][s], b.bary[l][s]) << "level " << l << ", vertex " << s;
  }
}

TEST(SkinBinding, TheFinestPointsParentTetsAreTheBindingLocatingAgainGives) {
  const GrownFinest g;
  const Skin skin = boundary_skin(g.meshes.back());
  const SkinBinding located = bind_skin(skin, g.locators);
  expect_same(bind_skin(skin, g.locators, &g.links.back().parent_tet), located);
  int outside = 0;  // the reused level has vertices outside its mesh: signed coordinates
  for (const Bary& b : located.bary[1]) outside += *std::min_element(b.begin(), b.end()) < 0;
  EXPECT_GT(outside, 0);
}

TEST(SkinBinding, ASkinThatIsNotTheFinestPointsIsLocatedAgain) {
  const GrownFinest g;
  Skin skin = boundary_skin(g.meshes.back());
  skin.rest[0].x() += 1e-9;  // still says it is point skin.point[0], but lies elsewhere
  const SkinBinding located = bind_skin(skin, g.locators);
  expect_same(bind_skin(skin, g.locators, &g.links.back().parent_tet), located);
  EXPECT_NE(located.bary[1][0], g.links.back().parent_tet.bary[skin.point[0]]);
}

}  // namespace
}  // namespace mrsim
