// Invariants of method.md §4.9 under randomized split/merge/GC sequences, and exact return to
// the initial state when everything is merged.
#include <gtest/gtest.h>

#include "hierarchy_fixture.hpp"

using namespace mrsim;
using namespace mrsim::testing;

namespace {

std::vector<std::pair<int, int>> candidates(const Hierarchy& h, bool split) {
  std::vector<std::pair<int, int>> c;
  for (int l = 0; l < h.num_levels(); ++l)
    for (int p = 0; p < h.num_points(l); ++p)
      if (split ? h.can_split(l, p) : h.can_merge(l, p)) c.emplace_back(l, p);
  return c;
}

void expect_initial(const Hierarchy& h) {
  for (int l = 0; l < h.num_levels(); ++l) {
    EXPECT_EQ(h.count(l, NodeState::Active), l == 0 ? h.num_points(0) : 0) << l;
    EXPECT_EQ(h.count(l, NodeState::GhostSub) + h.count(l, NodeState::GhostIface), 0) << l;
  }
}

}  // namespace

TEST(Hierarchy, LinksAreConsistent) {
  const ThreeLevels f;
  const auto links = build_level_links(f.levels);
  // Every finer point has exactly one parent: the children lists partition each finer level.
  for (int l = 0; l + 1 < 3; ++l) {
    std::vector<int> seen(f.meshes[l + 1].points.size(), 0);
    for (int p = 0; p < static_cast<int>(f.meshes[l].points.size()); ++p)
      for (int q : links[l].children.row(p)) {
        ++seen[q];
        EXPECT_EQ(links[l + 1].parent[q], p);
      }
    for (int s : seen) EXPECT_EQ(s, 1);
  }
  // Barycentric embeddings reproduce rest positions (inside or extrapolated).
  for (int l = 0; l < 3; ++l)
    for (size_t p = 0; p < f.meshes[l].points.size(); ++p) {
      if (l > 0) {
        Vec3 x = Vec3::Zero();
        const Tet& t = f.meshes[l - 1].tets[links[l].parent_tet.tet[p]];
        for (int a = 0; a < 4; ++a) x += links[l].parent_tet.bary[p][a] * f.meshes[l - 1].points[t[a]];
        EXPECT_LT((x - f.meshes[l].points[p]).norm(), 1e-12);
      }
      if (l < 2) {
        EXPECT_GE(links[l].child_tet.tet[p], 0);
      }
    }
}

TEST(Hierarchy, RandomSplitMergeKeepsInvariantsAndMergingAllRestoresTheStart) {
  const ThreeLevels f;
  Hierarchy h = f.make();
  ASSERT_TRUE(h.check_invariants().empty());
  std::mt19937 rng(123);
  int splits = 0, merges = 0;
  for (int op = 0; op < 3000; ++op) {
    const int kind = static_cast<int>(rng() % 10);
    if (kind < 5) {
      const auto c = candidates(h, true);
      if (c.empty()) continue;
      const auto [l, p] = c[rng() % c.size()];
      h.split(l, p);
      ++splits;
    } else if (kind < 9) {
      const auto c = candidates(h, false);
      if (c.empty()) continue;
      const auto [l, p] = c[rng() % c.size()];
      h.merge(l, p);
      ++merges;
    } else {
      h.collect_garbage();
    }
    const auto bad = h.check_invariants();
    ASSERT_TRUE(bad.empty()) << "after op " << op << ": " << bad.front();
  }
  EXPECT_GT(splits, 500);
  EXPECT_GT(merges, 500);
  // Leaves first, until nothing is subdivided.
  for (auto c = candidates(h, false); !c.empty(); c = candidates(h, false)) {
    for (auto [l, p] : c) {
      if (h.can_merge(l, p)) h.merge(l, p);
    }
    ASSERT_TRUE(h.check_invariants().empty());
  }
  h.collect_garbage();
  expect_initial(h);
}

TEST(Hierarchy, SplittingEverythingReachesTheFinestLevelEverywhere) {
  const ThreeLevels f;
  Hierarchy h = f.make();
  for (int l = 0; l + 1 < h.num_levels(); ++l)
    for (int p = 0; p < h.num_points(l); ++p)
      if (h.can_split(l, p)) h.split(l, p);
  EXPECT_TRUE(h.check_invariants().empty());
  EXPECT_EQ(h.count(2, NodeState::Active), h.num_points(2));  // every finest point simulated
  EXPECT_EQ(h.count(0, NodeState::Active), 0);
}
