// Which level simulates each part of the object (hierarchy/level_ownership.hpp): the shares add
// up to the object, follow splits and merges, and observe() says when they may have changed,
// which the VTK frames rely on to recount them only after a topology change.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "hierarchy/level_ownership.hpp"
#include "hierarchy_fixture.hpp"

using namespace mrsim;
using namespace mrsim::testing;

namespace {

struct Shares {
  std::vector<std::vector<double>> share;
  std::vector<std::vector<std::int8_t>> owner;
};

Shares shares_of(const LevelOwnership& own, int levels) {
  Shares s;
  s.share.resize(levels);
  s.owner.resize(levels);
  for (int l = 0; l < levels; ++l) own.shares(l, s.share[l], s.owner[l]);
  return s;
}

// Σ over levels and tets of share × volume, against the box's 0.1 × 0.06 × 0.04 m.
double simulated_volume(const ThreeLevels& f, const Shares& s) {
  double v = 0;
  for (std::size_t l = 0; l < f.meshes.size(); ++l)
    for (std::size_t t = 0; t < f.meshes[l].tets.size(); ++t) {
      const Tet& k = f.meshes[l].tets[t];
      const auto& x = f.meshes[l].points;
      v += s.share[l][t] * std::abs(signed_volume(x[k[0]], x[k[1]], x[k[2]], x[k[3]]));
    }
  return v;
}

}  // namespace

TEST(LevelOwnership, SharesCoverTheObjectFollowSplitsAndObserveSaysWhenTheyChange) {
  const ThreeLevels f;
  Hierarchy h = f.make();
  LevelOwnership own(h);
  constexpr double kBox = 0.1 * 0.06 * 0.04;
  EXPECT_TRUE(own.observe(h));   // the first observation
  EXPECT_FALSE(own.observe(h));  // nothing moved
  const Shares start = shares_of(own, 3);
  for (double s : start.share[0]) EXPECT_EQ(s, 1.0);  // level 0 alone simulates everything
  for (double s : start.share[1]) EXPECT_EQ(s, 0.0);
  EXPECT_NEAR(simulated_volume(f, start), kBox, 1e-12);

  // Split the level-0 points of the box's left half: level 1 takes a share there.
  for (int p = 0; p < h.num_points(0); ++p)
    if (f.meshes[0].points[p].x() < 0.05 && h.can_split(0, p)) h.split(0, p);
  EXPECT_TRUE(own.observe(h));
  EXPECT_FALSE(own.observe(h));
  const Shares split = shares_of(own, 3);
  double level1 = 0;
  for (double s : split.share[1]) level1 += s;
  EXPECT_GT(level1, 1.0);
  // The shares are sampled, so the object's volume only to the sampling.
  EXPECT_NEAR(simulated_volume(f, split), kBox, 0.03 * kBox);

  // Merged back: the coverage changes again, and the shares are the start's.
  for (int p = 0; p < h.num_points(0); ++p)
    if (h.can_merge(0, p)) h.merge(0, p);
  h.collect_garbage();
  EXPECT_TRUE(own.observe(h));
  const Shares back = shares_of(own, 3);
  EXPECT_EQ(back.share, start.share);
  EXPECT_EQ(back.owner, start.owner);

  // Observing skips the tets only while the hierarchy changed no status: a split and its merge
  // between two observations are changes (looked at again, found the same coverage) ...
  const std::uint64_t changes = h.status_changes();
  int p = 0;
  while (!h.can_split(0, p)) ++p;
  h.split(0, p);
  EXPECT_GT(h.status_changes(), changes);
  h.merge(0, p);
  h.collect_garbage();
  EXPECT_FALSE(own.observe(h));
  EXPECT_EQ(shares_of(own, 3).share, start.share);
  // ... and another hierarchy, even one with as many changes, is looked at too: two restored
  // from other counters have counted one change per point each.
  Hierarchy right = f.make(), rest = f.make();
  for (int q = 0; q < right.num_points(0); ++q)
    if (f.meshes[0].points[q].x() > 0.05 && right.can_split(0, q)) right.split(0, q);
  std::vector<HierarchyCounters> split_right, none;
  for (int l = 0; l < 3; ++l) {
    split_right.push_back(right.counters(l));
    none.push_back(rest.counters(l));
  }
  Hierarchy a = f.make(), b = f.make();
  a.restore(split_right);
  b.restore(none);
  ASSERT_EQ(a.status_changes(), b.status_changes());
  EXPECT_FALSE(own.observe(b));  // looked at: the start's coverage, as h's
  EXPECT_EQ(shares_of(own, 3).share, start.share);
  EXPECT_TRUE(own.observe(a));
  EXPECT_NE(shares_of(own, 3).share, start.share);
}

// The frames build the ownership with the simulation's own locators; the shares are those of
// the ownership that builds its own, in every coverage.
TEST(LevelOwnership, GivenLocatorsGiveTheSameShares) {
  const ThreeLevels f;
  Hierarchy h = f.make();
  std::vector<TetLocator> locators;
  for (const TetMesh& m : f.meshes) locators.emplace_back(m);
  LevelOwnership own(h), given(h, locators);
  for (int round = 0; round < 2; ++round) {
    own.observe(h);
    given.observe(h);
    const Shares a = shares_of(own, 3), b = shares_of(given, 3);
    EXPECT_EQ(a.share, b.share);
    EXPECT_EQ(a.owner, b.owner);
    for (int p = 0; p < h.num_points(0); ++p)
      if (f.meshes[0].points[p].x() < 0.05 && h.can_split(0, p)) h.split(0, p);
  }
}
