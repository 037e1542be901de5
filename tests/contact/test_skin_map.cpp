// SkinMap (contact/skin_map.hpp): each skin vertex follows the finest level whose bound tet has
// no inactive vertex, and its row is the interpolation row of hierarchy/active_row.hpp (the
// recursive expansion through ghosts) merged per point — now built once per point and shared,
// and each vertex's row merged only when asked for — so this checks the rows, asked for in a
// random order, against the plain recursion, over random split/merge/GC states of three
// independent box meshes with a Dirichlet face; and that a vertex's position interpolated in
// its level's tet is its row's value when the ghosts are current.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <algorithm>
#include <map>
#include <numeric>
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

// The three box levels with a Dirichlet face (z = 0), their skin bound to every level.
struct SkinOnThreeLevels {
  ThreeLevels f;
  Skin skin = boundary_skin(f.meshes.back());
  SkinBinding binding;
  std::vector<std::vector<std::uint8_t>> free;
  std::vector<const std::vector<std::uint8_t>*> free_point;
  SkinOnThreeLevels() : free(f.meshes.size()) {
    std::vector<const TetMesh*> meshes;
    for (const TetMesh& m : f.meshes) meshes.push_back(&m);
    binding = bind_skin(skin, meshes);
    for (std::size_t l = 0; l < f.meshes.size(); ++l) {
      for (const Vec3& X : f.meshes[l].points) free[l].push_back(X.z() > 1e-9 ? 1 : 0);
      free_point.push_back(&free[l]);
    }
  }
};

TEST(SkinMap, RowsAreTheMergedInterpolationRowsOfTheMovingTet) {
  const SkinOnThreeLevels c;
  const auto& [f, skin, binding, free, free_point] = c;
  Hierarchy h = f.make();
  SkinMap map;
  std::mt19937 rng(11);
  int through_ghosts = 0, held = 0, long_rows = 0;
  for (int round = 0; round < 30; ++round) {
    random_operations(h, rng, 15);
    ASSERT_TRUE(h.check_invariants().empty());
    map.build(h, binding, free_point);
    ASSERT_EQ(map.size(), static_cast<int>(skin.rest.size()));
    std::vector<int> order(map.size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    order.resize(order.size() / 2 + round);  // rows merged on demand: some, in any order
    for (int s : order) {
      const int l = map.level(s);
      ASSERT_EQ(l, expected_level(h, binding, s)) << "skin vertex " << s;
      std::vector<ActiveTerm> plain;
      const Tet& t = h.level(l).mesh->tets[binding.tet[l][s]];
      for (int k = 0; k < 4; ++k)
        if (binding.bary[l][s][k] != 0)
          append_active_row(h, free_point, l, t[k], binding.bary[l][s][k], plain);
      std::map<std::pair<int, int>, double> expected;
      for (const ActiveTerm& a : plain) expected[{a.level, a.point}] += a.weight;
      ASSERT_EQ(map.row(s).size(), expected.size()) << s;
      auto e = expected.begin();
      double sum = 0;
      for (const ActiveTerm& a : map.row(s)) {
        ASSERT_EQ(std::pair(a.level, a.point), e->first) << "skin vertex " << s;  // sorted
        EXPECT_NEAR(a.weight, e->second, 1e-14) << "skin vertex " << s;
        sum += a.weight;
        through_ghosts += a.level >= 0 && a.level != l;
        held += a.level < 0;
        ++e;
      }
      EXPECT_NEAR(sum, 1.0, 1e-12) << "a row reproduces a uniform displacement";
      long_rows += plain.size() > 16;
    }
  }
  EXPECT_GT(through_ghosts, 100);  // the states exercised the ghost chains
  EXPECT_GT(held, 10);             // and the Dirichlet face
  EXPECT_GT(long_rows, 10);        // and rows with points reached several times
}


// Every point's displacement as the hierarchy makes it: random on the free active points, zero
// on the held ones, a ghost's from its row (what the ghost refresh computes). A skin vertex's
// position from its level's tet is then its row's value.
TEST(SkinMap, InterpolatedPositionIsTheRowsValueWhenTheGhostsAreCurrent) {
  const SkinOnThreeLevels c;
  const auto& [f, skin, binding, free, free_point] = c;
  Hierarchy h = f.make();
  const int L = static_cast<int>(f.meshes.size());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  SkinMap map;
  int off_level = 0;
  for (int round = 0; round < 20; ++round) {
    random_operations(h, rng, 15);
    std::vector<std::vector<Vec3>> u(L), v(L);
    std::vector<LevelFields> fields(L);
    for (int l = 0; l < L; ++l) {
      // Inactive points hold NaN: a vertex of weight 0 may be one, and must not be read.
      u[l].assign(h.num_points(l), Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
      v[l] = u[l];
      for (int p = 0; p < h.num_points(l); ++p)
        if (h.state(l, p) == NodeState::Active) {
          u[l][p] = free[l][p] ? Vec3(r(rng), r(rng), r(rng)) : Vec3::Zero();
          v[l][p] = free[l][p] ? Vec3(r(rng), r(rng), r(rng)) : Vec3::Zero();
        }
      fields[l] = {u[l].data(), v[l].data()};
    }
    for (int l = 0; l < L; ++l)
      for (int p = 0; p < h.num_points(l); ++p) {
        const NodeState st = h.state(l, p);
        if (st != NodeState::GhostSub && st != NodeState::GhostIface) continue;
        std::vector<ActiveTerm> row;
        append_active_row(h, free_point, l, p, 1.0, row);
        Vec3 gu = Vec3::Zero(), gv = Vec3::Zero();
        for (const ActiveTerm& a : row) {
          if (a.level < 0) continue;  // held: at rest
          gu += a.weight * u[a.level][a.point];
          gv += a.weight * v[a.level][a.point];
        }
        u[l][p] = gu;
        v[l][p] = gv;
      }
    map.build(h, binding, free_point);
    for (int s = 0; s < map.size(); ++s) {
      Vec3 iu, iv;
      map.interpolate(s, fields, iu, iv);
      EXPECT_LE((iu - map.value(s, fields, false)).norm(), 1e-13) << "skin vertex " << s;
      EXPECT_LE((iv - map.value(s, fields, true)).norm(), 1e-13) << "skin vertex " << s;
      off_level += map.level(s) != 0;
    }
  }
  EXPECT_GT(off_level, 100);  // the states put the skin on finer levels, through ghosts
}

}  // namespace
}  // namespace mrsim
