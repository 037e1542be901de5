#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "contact/tool_shape.hpp"
#include "contact/tool_trajectory.hpp"

using namespace mrsim;

namespace {

const ToolShape kSphere{ToolShapeKind::Sphere, 1.0, 0.0};
const ToolShape kCapsule{ToolShapeKind::Capsule, 0.5, 2.0};
const ToolShape kPunch{ToolShapeKind::FlatCylinder, 1.0, 2.0};

void expect_probe(const ToolShape& s, const Vec3& p, double depth, const Vec3& normal) {
  const ShapeProbe got = probe(s, p);
  EXPECT_NEAR(got.depth, depth, 1e-12) << shape_name(s.kind) << " at " << p.transpose();
  EXPECT_LT((got.normal - normal.normalized()).norm(), 1e-12)
      << shape_name(s.kind) << " at " << p.transpose() << ": normal " << got.normal.transpose();
}

void expect_unit(const ShapeProbe& pr) {
  EXPECT_TRUE(std::isfinite(pr.depth));
  EXPECT_TRUE(pr.normal.allFinite());
  EXPECT_NEAR(pr.normal.norm(), 1.0, 1e-12);
}

std::vector<Vec3> random_points(double extent, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-extent, extent);
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i) points.emplace_back(d(rng), d(rng), d(rng) + 1.0);
  return points;
}

}  // namespace

TEST(ToolShape, SphereHandValues) {
  expect_probe(kSphere, Vec3(0.3, 0, 0), 0.7, Vec3::UnitX());
  expect_probe(kSphere, Vec3(0, 2, 0), -1.0, Vec3::UnitY());
  expect_probe(kSphere, Vec3(0.6, 0, -0.8), 0.0, Vec3(0.6, 0, -0.8));
  expect_probe(kSphere, Vec3(-3, 4, 0), -4.0, Vec3(-3, 4, 0));
  const ShapeProbe centre = probe(kSphere, Vec3::Zero());
  EXPECT_DOUBLE_EQ(centre.depth, 1.0);
  expect_unit(centre);
}

TEST(ToolShape, CapsuleHandValues) {
  expect_probe(kCapsule, Vec3(0.2, 0, 1), 0.3, Vec3::UnitX());           // shaft, inside
  expect_probe(kCapsule, Vec3(0, -0.9, 1.5), -0.4, -Vec3::UnitY());      // shaft, outside
  expect_probe(kCapsule, Vec3(0, 0, -0.2), 0.3, -Vec3::UnitZ());         // tip, inside
  expect_probe(kCapsule, Vec3(0, 0, -1.5), -1.0, -Vec3::UnitZ());        // below the tip
  expect_probe(kCapsule, Vec3(0, 0, 2.7), -0.2, Vec3::UnitZ());          // above the top cap
  expect_probe(kCapsule, Vec3(1, 0, 3), 0.5 - std::sqrt(2.0), Vec3(1, 0, 1));
  expect_probe(kCapsule, Vec3(0.3, 0, -0.4), 0.0, Vec3(0.3, 0, -0.4));   // on the tip sphere
}

TEST(ToolShape, PunchInsideTakesTheNearestFace) {
  expect_probe(kPunch, Vec3(0, 0, 0.1), 0.1, -Vec3::UnitZ());    // flat (working) face
  expect_probe(kPunch, Vec3(0.2, 0.1, 1.95), 0.05, Vec3::UnitZ());
  expect_probe(kPunch, Vec3(0.9, 0, 1), 0.1, Vec3::UnitX());
  expect_probe(kPunch, Vec3(0, -0.95, 1), 0.05, -Vec3::UnitY());
  expect_probe(kPunch, Vec3(0.6, 0.6, 0.5), 1 - 0.6 * std::sqrt(2.0), Vec3(1, 1, 0));
}

TEST(ToolShape, PunchOutsideIsTheExactDistance) {
  expect_probe(kPunch, Vec3(0.5, 0, -0.3), -0.3, -Vec3::UnitZ());        // below the face
  expect_probe(kPunch, Vec3(2, 0, 1), -1.0, Vec3::UnitX());              // beside
  expect_probe(kPunch, Vec3(0, 0.3, 2.4), -0.4, Vec3::UnitZ());          // above
  expect_probe(kPunch, Vec3(1.3, 0, -0.4), -0.5, Vec3(0.6, 0, -0.8));    // bottom rim
  expect_probe(kPunch, Vec3(0, 1.3, 2.4), -0.5, Vec3(0, 0.6, 0.8));      // top rim
  expect_probe(kPunch, Vec3(-1, 0, 0), 0.0, -Vec3::UnitZ());             // on the rim
}

TEST(ToolShape, RotatedPoseThroughToLocal) {
  // Punch turned so its handle points along -x: the flat face faces +x, at x = 1.
  ToolPose pose;
  pose.position = Vec3(1, 2, 3);
  pose.orientation = Quat(Eigen::AngleAxisd(-std::numbers::pi / 2, Vec3::UnitY()));
  ASSERT_LT((pose.orientation * Vec3::UnitZ() + Vec3::UnitX()).norm(), 1e-15);
  const auto world_probe = [&](const ToolShape& s, const Vec3& x) {
    ShapeProbe pr = probe(s, pose.to_local(x));
    pr.normal = pose.orientation * pr.normal;
    return pr;
  };
  ShapeProbe in = world_probe(kPunch, Vec3(0.95, 2.2, 3));
  EXPECT_NEAR(in.depth, 0.05, 1e-12);
  EXPECT_LT((in.normal - Vec3::UnitX()).norm(), 1e-12);
  ShapeProbe out = world_probe(kPunch, Vec3(1.3, 2.2, 3.1));
  EXPECT_NEAR(out.depth, -0.3, 1e-12);
  EXPECT_LT((out.normal - Vec3::UnitX()).norm(), 1e-12);
  // The capsule's shaft now runs along -x from (1, 2, 3): a point above it at z = 3.2.
  ShapeProbe shaft = world_probe(kCapsule, Vec3(0, 2, 3.2));
  EXPECT_NEAR(shaft.depth, 0.3, 1e-12);
  EXPECT_LT((shaft.normal - Vec3::UnitZ()).norm(), 1e-12);
}

TEST(ToolShape, DegeneratePointsGiveAFiniteUnitNormal) {
  for (const ToolShape& s : {kSphere, kCapsule, kPunch})
    for (double z : {-1.0, 0.0, 0.5, 1.0, 2.0, 3.0}) {
      SCOPED_TRACE(shape_name(s.kind) + " z=" + std::to_string(z));
      const ShapeProbe pr = probe(s, Vec3(0, 0, z));
      expect_unit(pr);
      EXPECT_EQ(pr.normal, probe(s, Vec3(0, 0, z)).normal);  // deterministic
    }
  EXPECT_DOUBLE_EQ(probe(kCapsule, Vec3(0, 0, 1)).depth, 0.5);
  EXPECT_DOUBLE_EQ(probe(kPunch, Vec3(0, 0, 1)).depth, 1.0);
}

// A signed distance is 1-Lipschitz, and stepping by h along the normal changes it by exactly
// -h (outside: the nearest point of a convex set stays; inside: the nearest face stays the
// nearest while h < depth). This checks depth and normal together at random points.
TEST(ToolShape, DepthIsContinuousAndNormalIsItsGradient) {
  const std::vector<Vec3> points = random_points(3.0, 4000, 11);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-1e-3, 1e-3);
  for (const ToolShape& s : {kSphere, kCapsule, kPunch}) {
    SCOPED_TRACE(shape_name(s.kind));
    int failures = 0;
    for (const Vec3& p : points) {
      const ShapeProbe pr = probe(s, p);
      const Vec3 q = p + Vec3(jitter(rng), jitter(rng), jitter(rng));
      if (std::abs(probe(s, q).depth - pr.depth) > (q - p).norm() + 1e-12) ++failures;
      const double h = pr.depth > 0 ? std::min(1e-3, 0.5 * pr.depth) : 1e-3;
      if (std::abs(probe(s, p + h * pr.normal).depth - (pr.depth - h)) > 1e-10) ++failures;
      if (std::abs(pr.normal.norm() - 1) > 1e-12) ++failures;
    }
    EXPECT_EQ(failures, 0);
  }
}

TEST(ToolShape, DepthIsContinuousAcrossTheSurface) {
  // Walk a line through each shape in small steps: no jumps, in particular at the surface.
  for (const ToolShape& s : {kSphere, kCapsule, kPunch}) {
    SCOPED_TRACE(shape_name(s.kind));
    const Vec3 a(-2.2, 0.3, -1.5), b(1.9, -0.2, 2.8);
    const int n = 20000;
    double previous = probe(s, a).depth;
    int inside = 0;
    for (int i = 1; i <= n; ++i) {
      const double d = probe(s, a + (b - a) * (double(i) / n)).depth;
      ASSERT_LE(std::abs(d - previous), (b - a).norm() / n + 1e-12) << "step " << i;
      inside += d > 0;
      previous = d;
    }
    EXPECT_GT(inside, 0);
    EXPECT_LT(inside, n);
  }
}

TEST(ToolShape, BoundingRadius) {
  EXPECT_DOUBLE_EQ(bounding_radius(kSphere), 1.0);
  EXPECT_DOUBLE_EQ(bounding_radius(kCapsule), 2.5);
  EXPECT_DOUBLE_EQ(bounding_radius(kPunch), std::sqrt(5.0));
  // The farthest points lie on the bound, and nothing inside lies beyond it.
  EXPECT_NEAR(probe(kCapsule, Vec3(0, 0, 2.5)).depth, 0, 1e-15);
  EXPECT_NEAR(probe(kPunch, Vec3(0, 1, 2)).depth, 0, 1e-15);
  for (const ToolShape& s : {kSphere, kCapsule, kPunch})
    for (const Vec3& p : random_points(3.0, 4000, 3))
      if (probe(s, p).depth >= 0) {
        EXPECT_LE(p.norm(), bounding_radius(s)) << shape_name(s.kind);
      }
}

TEST(ToolShape, Names) {
  EXPECT_EQ(shape_name(ToolShapeKind::Sphere), "sphere");
  EXPECT_EQ(shape_name(ToolShapeKind::Capsule), "capsule");
  EXPECT_EQ(shape_name(ToolShapeKind::FlatCylinder), "flat_cylinder");
}
