// SkinMap (contact/skin_map.hpp): each skin vertex follows the finest level whose bound tet has
// no inactive vertex, and its row is the interpolation row of hierarchy/active_row.hpp (the
// recursive expansion through ghosts) merged per point — now built once per point and shared,
// so this checks the shared rows against the plain recursion, over random split/merge/GC states
// of three independent box meshes with a Dirichlet face.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "../hierarchy/hierarchy_fixture.hpp"
#include "contact/skin.hpp"
#include "contact/skin_binding.hpp"
#include "contact/skin_map.hpp"

namespace mrsim {
namespace {

using testing::ThreeLevels;

int expected_level(const Hierarchy& h, const SkinBinding& b, int s) {
  for (int l = h.num_levels() - 1; l > 0; --l) {
    const Tet& t = h.level(l).mesh->tets[b.tet[l][s]];
    bool all = true;
    for (int k = 0; k < 4; ++k)
      all = all && (b.bary[l][s][k] == 0 || h.state(l, t[k]) != NodeState::Inactive);
    if (all) return l;
  }
  return 0;
}

void random_operations(Hierarchy& h, std::mt19937& rng, int count) {
  for (int op = 0; op < count; ++op) {
    const bool split = rng() % 3 != 0;
    std::vector<std::pair<int, int>> c;
    for (int l = 0; l < h.num_levels(); ++l)
      for (int p = 0; p < h.num_points(l); ++p)
        if (split ? h.can_split(l, p) : h.can_merge(l, p)) c.emplace_back(l, p);
    if (c.empty()) continue;
    const auto [l, p] = c[rng() % c.size()];
    split ? static_cast<void>(h.split(l, p)) : h.merge(l, p);
  }
  h.collect_garbage();
}

TEST(SkinMap, RowsAreTheMergedInterpolationRowsOfTheMovingTet) {
  const ThreeLevels f;
  Hierarchy h = f.make();
  const Skin skin = boundary_skin(f.meshes.back());
  std::vector<const TetMesh*> meshes;
  for (const TetMesh& m : f.meshes) meshes.push_back(&m);
  const SkinBinding binding = bind_skin(skin, meshes);
  std::vector<std::vector<std::uint8_t>> free(f.meshes.size());
  std::vector<const std::vector<std::uint8_t>*> free_point;
  for (std::size_t l = 0; l < f.meshes.size(); ++l) {
    for (const Vec3& X : f.meshes[l].points) free[l].push_back(X.z() > 1e-9 ? 1 : 0);
    free_point.push_back(&free[l]);
  }
  SkinMap map;
  std::mt19937 rng(11);
  int through_ghosts = 0, held = 0, long_rows = 0;
  for (int round = 0; round < 30; ++round) {
    random_operations(h, rng, 15);
    ASSERT_TRUE(h.check_invariants().empty());
    map.build(h, binding, free_point);
    ASSERT_EQ(map.size(), static_cast<int>(skin.rest.size()));
    for (int s = 0; s < map.size(); ++s) {
      const int l = map.level(s);
      ASSERT_EQ(l, expected_level(h, binding, s)) << "skin vertex " << s;
      std::vector<ActiveTerm> plain;
      const Tet& t = h.level(l).mesh->tets[binding.tet[l][s]];
      for (int k = 0; k < 4; ++k)
        if (binding.bary[l][s][k] != 0)
          append_active_row(h, free_point, l, t[k], binding.bary[l][s][k], plain);
      std::map<std::pair<int, int>, double> expected;
      for (const ActiveTerm& a : plain) expected[{a.level, a.point}] += a.weight;
      ASSERT_EQ(static_cast<std::size_t>(map.end(s) - map.begin(s)), expected.size()) << s;
      auto e = expected.begin();
      double sum = 0;
      for (const ActiveTerm* a = map.begin(s); a != map.end(s); ++a, ++e) {
        ASSERT_EQ(std::pair(a->level, a->point), e->first) << "skin vertex " << s;  // sorted
        EXPECT_NEAR(a->weight, e->second, 1e-14) << "skin vertex " << s;
        sum += a->weight;
        through_ghosts += a->level >= 0 && a->level != l;
        held += a->level < 0;
      }
      EXPECT_NEAR(sum, 1.0, 1e-12) << "a row reproduces a uniform displacement";
      long_rows += plain.size() > 16;
    }
  }
  EXPECT_GT(through_ghosts, 100);  // the states exercised the ghost chains
  EXPECT_GT(held, 10);             // and the Dirichlet face
  EXPECT_GT(long_rows, 10);        // and rows with points reached several times
}

}  // namespace
}  // namespace mrsim
