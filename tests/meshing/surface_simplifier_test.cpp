// The topology-preserving simplifier and the shape improvement behind the fallback for
// surfaces gmsh cannot remesh: genus and manifoldness kept, no self-intersection, volume kept,
// the triangle count reached when the topology allows it, deterministic. On a thin torus
// (a narrow handle, like the femur's) built here, and on the femur itself.
#include <cmath>
#include <numbers>

#include "meshing/editable_surface.hpp"
#include "meshing/self_intersection.hpp"
#include "meshing/surface_checks.hpp"
#include "meshing/surface_improvement.hpp"
#include "meshing/surface_readers.hpp"
#include "meshing/surface_simplifier.hpp"
#include "meshing/surface_topology.hpp"
#include "meshing_test_support.hpp"

namespace mrsim::test {
namespace {

/// A torus around z (ring radius R, tube radius r), nu x nv quads split in two, outward.
SurfaceMesh torus(double R, double r, int nu, int nv) {
  SurfaceMesh s;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double u = 2.0 * std::numbers::pi * i / nu, v = 2.0 * std::numbers::pi * j / nv;
      s.points.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  }
  auto at = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  s.face_of.resize(s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t) s.face_of[t] = static_cast<int>(t) + 1;
  if (enclosed_volume(s) < 0.0) {
    for (Triangle& t : s.triangles) std::swap(t[1], t[2]);
  }
  return s;
}

double mean_quality(const SurfaceMesh& s) {
  double sum = 0.0;
  for (const Triangle& t : s.triangles) sum += triangle_quality(s.points[t[0]], s.points[t[1]], s.points[t[2]]);
  return sum / static_cast<double>(s.triangles.size());
}

/// Closed, manifold, consistently oriented, not crossing itself, of the given genus, and
/// enclosing `volume` (collapses keep the volume exactly, up to round-off).
void expect_valid(SurfaceMesh s, int genus, double volume) {
  EXPECT_NO_THROW(check_edges_closed(s, "simplified"));
  EXPECT_NO_THROW(check_vertex_fans(s, "simplified"));
  EXPECT_EQ(orient_consistently(s, "simplified"), 0);
  EXPECT_EQ(find_self_intersections(s).pairs, 0u);
  EXPECT_EQ(connected_components(s), 1);
  EXPECT_EQ(surface_genus(s), genus);
  EXPECT_NEAR(enclosed_volume(s) / volume, 1.0, 1e-6);
}

TEST(SurfaceSimplifier, ThinTorusKeepsItsHandle) {
  const SurfaceMesh input = torus(0.1, 0.01, 96, 24);  // 4608 triangles
  const double volume = enclosed_volume(input);
  const SimplifiedSurface coarse = simplify_surface(input, {.target_triangles = 200});
  EXPECT_TRUE(coarse.reached_target);
  EXPECT_EQ(coarse.surface.triangles.size(), 200u);
  expect_valid(coarse.surface, 1, volume);

  // Far below what a torus can have (at least 7 vertices, 14 triangles): the link condition
  // stops the collapses instead of closing the handle.
  const SimplifiedSurface floor = simplify_surface(input, {.target_triangles = 4});
  EXPECT_FALSE(floor.reached_target);
  EXPECT_GE(floor.surface.triangles.size(), 14u);
  expect_valid(floor.surface, 1, volume);
}

TEST(SurfaceSimplifier, IsDeterministic) {
  const SurfaceMesh input = torus(0.1, 0.03, 48, 16);
  const SimplifiedSurface a = simplify_surface(input, {.target_triangles = 300});
  const SimplifiedSurface b = simplify_surface(input, {.target_triangles = 300});
  EXPECT_TRUE(a.surface.points == b.surface.points);
  EXPECT_TRUE(a.surface.triangles == b.surface.triangles);
}

TEST(SurfaceSimplifier, FemurKeepsGenusTwo) {
  MRSIM_REQUIRE_SHARED_DATA();
  SurfaceMesh input = read_surface(shared_data() / "cgal" / "femur.off");
  const SurfaceCheckReport checks = check_surface(input, "femur.off");
  for (std::size_t target : {300u, 2000u}) {
    const SimplifiedSurface simplified = simplify_surface(input, {.target_triangles = target});
    EXPECT_TRUE(simplified.reached_target) << target;
    EXPECT_EQ(simplified.surface.triangles.size(), target);
    expect_valid(simplified.surface, checks.genus, checks.enclosed_volume);
  }
}

TEST(SurfaceImprovement, BetterShapesSameTopology) {
  MRSIM_REQUIRE_SHARED_DATA();
  SurfaceMesh input = read_surface(shared_data() / "cgal" / "femur.off");
  const SurfaceCheckReport checks = check_surface(input, "femur.off");
  const SurfaceMesh simplified = simplify_surface(input, {.target_triangles = 1000}).surface;
  const SurfaceMesh improved = improve_triangle_shapes(simplified);
  EXPECT_EQ(improved.triangles.size(), simplified.triangles.size());
  EXPECT_GT(mean_quality(improved), mean_quality(simplified) + 0.02);
  EXPECT_NO_THROW(check_edges_closed(improved, "improved"));
  EXPECT_NO_THROW(check_vertex_fans(improved, "improved"));
  EXPECT_EQ(find_self_intersections(improved).pairs, 0u);
  EXPECT_EQ(surface_genus(improved), checks.genus);
  // Smoothing moves points within their tangent planes: the volume changes only a little.
  EXPECT_NEAR(enclosed_volume(improved) / checks.enclosed_volume, 1.0, 0.005);
}

}  // namespace
}  // namespace mrsim::test
