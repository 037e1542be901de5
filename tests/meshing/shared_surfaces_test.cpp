// The real surfaces of ../shared/data/cgal: each defective one is rejected with its reason,
// the good ones pass the checks (skipped when ../shared is absent).
#include "meshing/surface_checks.hpp"
#include "meshing/surface_readers.hpp"
#include "meshing_test_support.hpp"

namespace mrsim::test {
namespace {

SurfaceCheckReport check_shared(const std::string& name) {
  const auto file = shared_data() / "cgal" / name;
  SurfaceMesh s = read_surface(file);
  return check_surface(s, file.string());
}

TEST(SharedSurfaces, DefectsAreRejectedWithTheirReason) {
  MRSIM_REQUIRE_SHARED_DATA();
  expect_input_error([] { check_shared("head.off"); }, {"head.off", "open surface", "58 boundary edges"});
  expect_input_error([] { check_shared("bones.off"); }, {"bones.off", "self-intersecting"});
  expect_input_error([] { check_shared("cow.off"); }, {"cow.off", "1 pinched vertex"});
  expect_input_error([] { check_shared("mpi.off"); }, {"mpi.off", "2 zero-area triangles", "face"});
}

TEST(SharedSurfaces, GoodSurfacesPass) {
  MRSIM_REQUIRE_SHARED_DATA();
  EXPECT_NEAR(check_shared("cube-meshed.off").enclosed_volume, 8.0, 1e-9);
  EXPECT_NEAR(check_shared("sphere.off").enclosed_volume, 3.14159 / 6.0, 0.03);
  EXPECT_GT(check_shared("ellipsoid.off").enclosed_volume, 0.0);
  EXPECT_EQ(check_shared("femur.off").genus, 2);
  EXPECT_EQ(check_shared("bunny00.off").genus, 0);
  EXPECT_EQ(check_shared("armadillo.off").genus, 0);
}

TEST(SharedSurfaces, LiverSurfacesInEveryFormatAgree) {
  MRSIM_REQUIRE_SHARED_DATA();
  const auto dir = shared_data() / "liver_cgal";
  SurfaceMesh off = read_surface(dir / "liver_cgal_h14_surface.off");
  SurfaceMesh stl = read_surface(dir / "liver_cgal_h14_surface.stl");
  const double v_off = check_surface(off, "off").enclosed_volume;
  const double v_stl = check_surface(stl, "stl").enclosed_volume;
  EXPECT_EQ(off.points.size(), stl.points.size());  // STL's repeated corners are welded
  EXPECT_NEAR(v_stl / v_off, 1.0, 1e-5);            // STL stores floats
  EXPECT_NEAR(v_off, 1.74e6, 0.05e6);               // mm^3, SOURCES.md
}

}  // namespace
}  // namespace mrsim::test
