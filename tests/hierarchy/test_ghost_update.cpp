// Cross-level consistency of ghosts (issue 4 point 6): a linear displacement field is reproduced
// exactly by every ghost and every inactive point, whatever the mix of levels; the working lists
// always match the statuses.
#include <gtest/gtest.h>

#include <random>

#include "hierarchy/ghost_update.hpp"
#include "hierarchy_fixture.hpp"

using namespace mrsim;
using namespace mrsim::testing;

namespace {

void expect_lists_match(const Hierarchy& h, const StatusLists& lists) {
  for (int l = 0; l < h.num_levels(); ++l) {
    std::vector<int> a, s, i;
    for (int p = 0; p < h.num_points(l); ++p) {
      const NodeState st = h.state(l, p);
      if (st == NodeState::Active) a.push_back(p);
      if (st == NodeState::GhostSub) s.push_back(p);
      if (st == NodeState::GhostIface) i.push_back(p);
    }
    ASSERT_EQ(lists.active(l), a) << l;
    ASSERT_EQ(lists.ghost_sub(l), s) << l;
    ASSERT_EQ(lists.ghost_iface(l), i) << l;
    // Each ghost's sources are its tet's vertices in the neighbouring level (what the ghost
    // refresh and the force transfer read).
    auto expect_sources = [&](const std::vector<int>& ghosts, const Embedding& emb,
                              const TetMesh& source) {
      for (int g : ghosts) EXPECT_EQ(emb.source[g], source.tets[emb.tet[g]]) << l;
    };
    if (!s.empty()) expect_sources(s, h.links(l).child_tet, *h.level(l + 1).mesh);
    if (!i.empty()) expect_sources(i, h.links(l).parent_tet, *h.level(l - 1).mesh);
  }
}

}  // namespace

TEST(GhostUpdate, LinearFieldIsReproducedExactlyAcrossLevels) {
  const ThreeLevels f;
  Hierarchy h = f.make();
  StatusLists lists(h);
  std::mt19937 rng(5);
  Mat3 A;
  A << 1e-2, 3e-3, -2e-3, 4e-3, -1e-2, 2e-3, -3e-3, 1e-3, 2e-2;
  const Vec3 b(1e-3, -2e-3, 5e-4);
  std::vector<std::vector<Vec3>> u(3), v(3);
  std::vector<LevelFields> fields(3);
  std::size_t iface_seen = 0, sub_seen = 0;
  for (int round = 0; round < 40; ++round) {
    for (int k = 0; k < 15; ++k) {  // a few random splits and merges per round
      std::vector<std::pair<int, int>> c;
      const bool split = rng() % 3 != 0;
      for (int l = 0; l < 3; ++l)
        for (int p = 0; p < h.num_points(l); ++p)
          if (split ? h.can_split(l, p) : h.can_merge(l, p)) c.emplace_back(l, p);
      if (c.empty()) continue;
      const auto [l, p] = c[rng() % c.size()];
      split ? (void)h.split(l, p) : h.merge(l, p);
    }
    if (round % 4 == 0) h.collect_garbage();
    lists.update(h, h.take_touched());
    expect_lists_match(h, lists);
    // Active points carry the exact field, everything else garbage: ghosts must recover it.
    for (int l = 0; l < 3; ++l) {
      u[l].assign(h.num_points(l), Vec3(1e9, 1e9, 1e9));
      v[l].assign(h.num_points(l), Vec3(1e9, 1e9, 1e9));
      for (int p : lists.active(l)) {
        u[l][p] = A * f.meshes[l].points[p] + b;
        v[l][p] = 2 * u[l][p];
      }
      fields[l] = {u[l].data(), v[l].data()};
    }
    iface_seen += lists.total(StatusLists::kGhostIface);
    sub_seen += lists.total(StatusLists::kGhostSub);
    update_ghosts(h, lists, fields);
    interpolate_inactive(h, fields);
    for (int l = 0; l < 3; ++l)
      for (int p = 0; p < h.num_points(l); ++p) {
        const Vec3 exact = A * f.meshes[l].points[p] + b;
        ASSERT_LT((u[l][p] - exact).norm(), 1e-14) << "level " << l << " point " << p << " "
                                                   << node_state_name(h.state(l, p));
        ASSERT_LT((v[l][p] - 2 * exact).norm(), 1e-14);
      }
  }
  EXPECT_GT(iface_seen, 100u);  // the test exercised both kinds of ghosts
  EXPECT_GT(sub_seen, 100u);
}
