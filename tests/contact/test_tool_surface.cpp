#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>

#include "contact/tool_shape.hpp"
#include "contact/tool_surface.hpp"

using namespace mrsim;

namespace {

constexpr double kPi = std::numbers::pi;

struct Case {
  ToolShape shape;
  double volume;  // analytic
};

std::vector<Case> cases() {
  const double r = 0.02, L = 0.05;
  return {{{ToolShapeKind::Sphere, r, 0}, 4.0 / 3.0 * kPi * r * r * r},
          {{ToolShapeKind::Capsule, r, L}, kPi * r * r * L + 4.0 / 3.0 * kPi * r * r * r},
          {{ToolShapeKind::FlatCylinder, r, L}, kPi * r * r * L},
          {{ToolShapeKind::Capsule, r, 0}, 4.0 / 3.0 * kPi * r * r * r},  // degenerates to a ball
          {{ToolShapeKind::FlatCylinder, 0.5, 0.01}, kPi * 0.25 * 0.01}};  // a thin disc
}

std::string label(const ToolShape& s, int segments) {
  return shape_name(s.kind) + " r=" + std::to_string(s.radius) + " L=" + std::to_string(s.length) +
         " segments=" + std::to_string(segments);
}

Vec3 corner(const TriangleSurface& s, const std::array<int, 3>& t, int i) { return s.points[t[i]]; }

Vec3 area_normal(const TriangleSurface& s, const std::array<int, 3>& t) {
  return 0.5 * (corner(s, t, 1) - corner(s, t, 0)).cross(corner(s, t, 2) - corner(s, t, 0));
}

// Divergence theorem: sum of signed tetrahedra against the origin; positive when outward.
double enclosed_volume(const TriangleSurface& s) {
  double v = 0;
  for (const auto& t : s.triangles)
    v += corner(s, t, 0).dot(corner(s, t, 1).cross(corner(s, t, 2))) / 6.0;
  return v;
}

// Each directed edge once and its reverse once: closed, manifold, consistently oriented.
void expect_closed(const TriangleSurface& s) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : s.triangles)
    for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
  int bad = 0;
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) ++bad;
  }
  EXPECT_EQ(bad, 0);
  // Euler characteristic of a sphere: V - E + F = 2 (also catches unused or duplicate points).
  const long edges = static_cast<long>(directed.size()) / 2;
  EXPECT_EQ(static_cast<long>(s.points.size()) - edges + static_cast<long>(s.triangles.size()), 2);
}

}  // namespace

TEST(ToolSurface, ClosedOutwardAndOnTheShape) {
  for (const Case& c : cases())
    for (int segments : {8, 24, 37}) {
      SCOPED_TRACE(label(c.shape, segments));
      const TriangleSurface s = tool_surface(c.shape, segments);
      ASSERT_FALSE(s.triangles.empty());
      for (const auto& t : s.triangles)
        for (int i : t) ASSERT_TRUE(i >= 0 && i < static_cast<int>(s.points.size()));
      expect_closed(s);
      const double r = c.shape.radius;
      for (const Vec3& p : s.points) ASSERT_LT(std::abs(probe(c.shape, p).depth), 1e-12 * r);
      // The shapes are convex and the vertices on their surface, so every facet lies just
      // inside, and faces away from an interior point (the middle of the axis).
      const Vec3 middle(0, 0, 0.5 * c.shape.length);
      const bool punch = c.shape.kind == ToolShapeKind::FlatCylinder;
      const double inradius = punch ? std::min(r, 0.5 * c.shape.length) : r;  // about middle
      double sagitta = 0;
      for (const auto& t : s.triangles) {
        const Vec3 n = area_normal(s, t);
        ASSERT_GT(n.norm(), 1e-9 * r * r);
        const Vec3 centroid = (corner(s, t, 0) + corner(s, t, 1) + corner(s, t, 2)) / 3.0;
        const double depth = probe(c.shape, centroid).depth;
        EXPECT_GE(depth, -1e-12 * r);
        sagitta = std::max(sagitta, depth);
        EXPECT_GT(n.normalized().dot(centroid - middle), 0.5 * inradius);
      }
      // A facet spans at most one angular step: no deeper than r (1 - cos step).
      EXPECT_LT(sagitta, r * (1 - std::cos(2 * kPi / segments)));
    }
}

TEST(ToolSurface, VolumeApproachesTheShape) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(label(c.shape, 24));
    const double v24 = enclosed_volume(tool_surface(c.shape, 24));
    EXPECT_GT(v24, 0);
    EXPECT_LT(v24, c.volume);  // inscribed
    EXPECT_NEAR(v24 / c.volume, 1.0, 0.04);
    const double v96 = enclosed_volume(tool_surface(c.shape, 96));
    EXPECT_NEAR(v96 / c.volume, 1.0, 0.003);
  }
}

TEST(ToolSurface, SegmentsAroundTheAxis) {
  const ToolShape punch{ToolShapeKind::FlatCylinder, 1.0, 2.0};
  // Two poles and two rims of `segments` points; 4 triangles per segment.
  const TriangleSurface s = tool_surface(punch, 24);
  EXPECT_EQ(s.points.size(), 2u + 2u * 24u);
  EXPECT_EQ(s.triangles.size(), 4u * 24u);
  // Fewer than 8 is raised to 8.
  for (int few : {-3, 0, 3, 7}) {
    const TriangleSurface f = tool_surface(punch, few);
    EXPECT_EQ(f.points.size(), 2u + 2u * 8u) << few;
    EXPECT_EQ(f.triangles.size(), 4u * 8u) << few;
  }
  const ToolShape sphere{ToolShapeKind::Sphere, 1.0, 0};
  EXPECT_EQ(tool_surface(sphere, 3).triangles.size(), tool_surface(sphere, 8).triangles.size());
}
