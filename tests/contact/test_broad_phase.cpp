// The broad phase (SkinContact::near_tools, once per display frame): the skin vertices within
// the tool's reach of its path over the frame; and the set-up's version over the whole run
// (reachable_skin, for the contact bound of the computed substeps). Most of the skin is far from
// the tool and is passed on the path's bounding box alone; that shortcut may not change which
// vertices are found.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../hierarchy/hierarchy_fixture.hpp"
#include "contact/contact_bound.hpp"
#include "contact/skin_contact.hpp"

namespace mrsim {
namespace {

double distance_to_segment(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double len2 = d.squaredNorm();
  const double s = len2 > 0 ? std::clamp((x - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (x - (a + s * d)).norm();
}

// The three-level box's boundary skin, bound to its levels with every point free, and zero
// displacement and velocity fields (u, shared as v) that a test may change.
struct BoxSkin {
  testing::ThreeLevels f;
  Hierarchy h = f.make();
  Skin skin = boundary_skin(f.meshes.back());
  std::vector<std::vector<std::uint8_t>> free;
  std::vector<const std::vector<std::uint8_t>*> free_point;
  std::vector<std::vector<Vec3>> u;
  std::vector<LevelFields> fields;

  BoxSkin() {
    free.resize(f.meshes.size());
    u.resize(f.meshes.size());
    for (std::size_t l = 0; l < f.meshes.size(); ++l) {
      free[l].assign(f.meshes[l].points.size(), 1);
      free_point.push_back(&free[l]);
      u[l].assign(f.meshes[l].points.size(), Vec3::Zero());
      fields.push_back({u[l].data(), u[l].data()});
    }
  }
  SkinContact contact(const Tool& tool) const {
    std::vector<const TetMesh*> meshes;
    for (const TetMesh& m : f.meshes) meshes.push_back(&m);
    SkinContact c(skin, bind_skin(skin, meshes), {tool}, 1e5);
    c.remap(h, free_point);
    return c;
  }
};

TEST(BroadPhase, FindsEveryVertexWithinReachOfTheSampledPathAndNoOther) {
  const BoxSkin box;
  const Skin& skin = box.skin;
  const std::vector<LevelFields>& fields = box.fields;
  Tool tool;
  tool.shape.kind = ToolShapeKind::Sphere;
  tool.shape.radius = 0.006;
  // A curved pass over the top face (z = 0.04) of the 0.1 × 0.06 × 0.04 m box, and beyond it.
  tool.trajectory = ToolTrajectory({{0.0, Vec3(-0.01, 0.01, 0.05)},
                                    {0.5, Vec3(0.05, 0.05, 0.043)},
                                    {1.0, Vec3(0.12, 0.02, 0.06)}},
                                   Interpolation::Smooth, "tool");
  SkinContact contact = box.contact(tool);
  int near_total = 0;
  for (int frame = 0; frame < 10; ++frame) {
    const double t0 = 0.1 * frame, t1 = t0 + 0.1;
    std::vector<std::vector<int>> found;
    contact.near_tools(t0, t1, fields, found);
    // The rule in full: 16 poses over the frame, reach = 1.05 × the bounding radius (the skin
    // is at rest), plus the longest chord between two poses.
    constexpr int kSamples = 16;
    std::vector<Vec3> path;
    for (int i = 0; i <= kSamples; ++i)
      path.push_back(tool.trajectory.pose(t0 + (t1 - t0) * i / kSamples).position);
    double chord = 0;
    for (int i = 1; i <= kSamples; ++i) chord = std::max(chord, (path[i] - path[i - 1]).norm());
    const double reach = 1.05 * tool.shape.radius + chord;
    std::vector<int> expected;
    for (int s = 0; s < static_cast<int>(skin.rest.size()); ++s) {
      double d = (skin.rest[s] - path[0]).norm();
      for (int i = 1; i <= kSamples; ++i)
        d = std::min(d, distance_to_segment(skin.rest[s], path[i - 1], path[i]));
      if (d <= reach) expected.push_back(s);
    }
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0], expected) << "frame " << frame;
    near_total += static_cast<int>(expected.size());
  }
  EXPECT_GT(near_total, 20);  // the tool does come near the skin
}


TEST(BroadPhase, ReachableSkinOfARunIsEveryVertexNearOneOfItsSamplesAndNoOther) {
  const testing::ThreeLevels f;
  const Skin skin = boundary_skin(f.meshes.back());
  std::vector<Tool> tools(2);
  tools[0].shape.kind = ToolShapeKind::Sphere;
  tools[0].shape.radius = 0.004;
  tools[0].trajectory = ToolTrajectory({{0.0, Vec3(-0.01, 0.01, 0.05)},
                                        {0.5, Vec3(0.05, 0.05, 0.043)},
                                        {1.0, Vec3(0.12, 0.02, 0.06)}},
                                       Interpolation::Smooth, "a");
  tools[1].shape.kind = ToolShapeKind::Sphere;
  tools[1].shape.radius = 0.003;
  // Along the face x = 0, 5 mm outside it: its box is a segment, and the skin it reaches lies
  // beside that segment, not within its box.
  tools[1].trajectory = ToolTrajectory({{0.0, Vec3(-0.005, -0.01, 0.02)},
                                        {1.0, Vec3(-0.005, 0.07, 0.02)}},
                                       Interpolation::Linear, "b");
  const double duration = 1.0, frame_dt = 0.05;
  const std::vector<int> found = reachable_skin(skin, tools, duration, frame_dt);
  // The rule in full: every sample of every tool, reach twice its bounding radius.
  const int samples = 16 * 20;
  std::vector<int> expected;
  for (int s = 0; s < static_cast<int>(skin.rest.size()); ++s) {
    bool near = false;
    for (const Tool& tool : tools)
      for (int k = 0; k <= samples && !near; ++k)
        near = (tool.trajectory.pose(duration * k / samples).position - skin.rest[s]).norm() <
               2 * tool.shape.radius;
    if (near) expected.push_back(s);
  }
  EXPECT_EQ(found, expected);
  EXPECT_GT(expected.size(), 20u);                   // both tools pass near the skin
  EXPECT_LT(expected.size(), skin.rest.size() / 2);  // and most of it is out of reach
}

// A call with the version of the last one takes its skin positions and speed again (the state
// did not change), version 0 or another version interpolates them anew, and a remap (the skin
// follows other points) forgets them.
TEST(BroadPhase, SkinPositionsAreKeptForTheirVersionUntilTheSkinIsRemapped) {
  BoxSkin box;
  std::vector<std::vector<Vec3>>& u = box.u;
  const std::vector<LevelFields>& fields = box.fields;
  Tool tool;
  tool.shape.kind = ToolShapeKind::Sphere;
  tool.shape.radius = 0.006;
  tool.trajectory = ToolTrajectory({{0.0, Vec3(0.05, 0.03, 0.05)}, {1.0, Vec3(0.05, 0.03, 0.05)}},
                                   Interpolation::Linear, "tool");
  SkinContact contact = box.contact(tool);
  std::vector<std::vector<int>> at_rest, found;
  contact.near_tools(0, 0.1, fields, at_rest, 7);
  for (auto& level : u) std::fill(level.begin(), level.end(), Vec3(0, 0, 0.008));  // 8 mm up
  contact.near_tools(0, 0.1, fields, found, 7);
  EXPECT_EQ(found, at_rest);  // version 7's positions: at rest
  std::vector<std::vector<int>> raised;
  contact.near_tools(0, 0.1, fields, raised, 8);
  EXPECT_NE(raised, at_rest);  // the raised skin is nearer the tool
  contact.near_tools(0, 0.1, fields, found, 0);
  EXPECT_EQ(found, raised);
  contact.near_tools(0, 0.1, fields, found, 9);
  for (auto& level : u) std::fill(level.begin(), level.end(), Vec3::Zero());
  contact.remap(box.h, box.free_point);
  contact.near_tools(0, 0.1, fields, found, 9);
  EXPECT_EQ(found, at_rest);  // computed again after the remap
}

}  // namespace
}  // namespace mrsim
