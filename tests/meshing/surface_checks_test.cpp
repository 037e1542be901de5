// Every kind of bad surface is rejected with its own reason; repairable orientation is fixed.
#include "meshing/surface_checks.hpp"
#include "meshing/surface_readers.hpp"
#include "meshing_test_support.hpp"

namespace mrsim::test {
namespace {

SurfaceCheckReport check_file(const std::filesystem::path& file) {
  SurfaceMesh s = read_surface(file);
  return check_surface(s, file.string());
}

TEST(SurfaceChecks, OpenSurface) {
  ScratchDir dir;
  const auto file = dir.write("open.off", cube_off("0 0 0", 11));
  expect_input_error([&] { check_file(file); }, {"open.off", "open surface", "3 boundary edges"});
}

TEST(SurfaceChecks, NonFiniteCoordinate) {
  ScratchDir dir;
  const auto file = dir.write("nan.off", cube_off("0 nan 0"));
  expect_input_error([&] { check_file(file); }, {"nan.off", "vertex 1", "non-finite"});
  const auto inf = dir.write("inf.off", cube_off("inf 0 0"));
  expect_input_error([&] { check_file(inf); }, {"non-finite"});
}

TEST(SurfaceChecks, ZeroAreaTriangleFromAPolygon) {
  // A pentagon whose fan gives a flat triangle: corners 0, 1, 2 collinear.
  ScratchDir dir;
  const auto file = dir.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 1 0.5 1\n"
                                          "f 1 2 3 4 5\nf 1 2 6\nf 2 3 6\nf 3 4 6\nf 4 5 6\nf 5 1 6\n");
  expect_input_error([&] { check_file(file); }, {"flat.obj", "zero-area triangle", "face 1"});
}

TEST(SurfaceChecks, PinchedVertex) {
  // Two tetrahedra touching at one vertex: every edge has two triangles, the vertex two fans.
  ScratchDir dir;
  const auto file = dir.write("pinched.off", "OFF\n7 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n0 -1 0\n0 0 -1\n"
                                             "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
                                             "3 0 5 4\n3 0 4 6\n3 0 6 5\n3 4 5 6\n");
  expect_input_error([&] { check_file(file); }, {"pinched.off", "pinched vertex", "(0, 0, 0)"});
}

TEST(SurfaceChecks, NonManifoldEdge) {
  ScratchDir dir;
  const auto file = dir.write("fin.off", cube_off("0 0 0", 14, "3 0 1 6\n3 0 6 1\n"));
  expect_input_error([&] { check_file(file); }, {"fin.off", "non-manifold"});
}

TEST(SurfaceChecks, SelfIntersectingParts) {
  // The unit cube and a second cube crossing it.
  ScratchDir dir;
  std::string two = "OFF\n16 24 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                    "0.5 0.5 0.5\n1.5 0.5 0.5\n1.5 1.5 0.5\n0.5 1.5 0.5\n0.5 0.5 1.5\n1.5 0.5 1.5\n1.5 1.5 1.5\n0.5 1.5 1.5\n";
  const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                            {2, 3, 7}, {2, 7, 6}, {1, 2, 6}, {1, 6, 5}, {0, 4, 7}, {0, 7, 3}};
  for (int offset : {0, 8}) {
    for (const auto& f : faces) {
      two += "3 " + std::to_string(f[0] + offset) + " " + std::to_string(f[1] + offset) + " " +
             std::to_string(f[2] + offset) + "\n";
    }
  }
  const auto file = dir.write("two.off", two);
  expect_input_error([&] { check_file(file); }, {"two.off", "self-intersecting"});
}

TEST(SurfaceChecks, SeparatePartsAreOneBodyTooMany) {
  ScratchDir dir;
  std::string two = "OFF\n8 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 0 0\n6 0 0\n5 1 0\n5 0 1\n";
  for (int offset : {0, 4}) {
    for (const char* f : {"0 2 1", "0 1 3", "0 3 2", "1 2 3"}) {
      int a, b, c;
      std::sscanf(f, "%d %d %d", &a, &b, &c);
      two += "3 " + std::to_string(a + offset) + " " + std::to_string(b + offset) + " " + std::to_string(c + offset) + "\n";
    }
  }
  const auto file = dir.write("apart.off", two);
  expect_input_error([&] { check_file(file); }, {"apart.off", "2 separate closed parts"});
}

TEST(SurfaceChecks, OrientationIsRepairedAndTurnedOutward) {
  ScratchDir dir;
  // One face flipped (3 0 1 2 instead of 3 0 2 1), then the whole cube inside out.
  std::string flipped = cube_off();
  flipped.replace(flipped.find("3 0 2 1"), 7, "3 0 1 2");
  SurfaceMesh s = read_surface(dir.write("flipped.off", flipped));
  SurfaceCheckReport r = check_surface(s, "flipped.off");
  EXPECT_EQ(r.flipped_triangles, 1);
  EXPECT_NEAR(r.enclosed_volume, 1.0, 1e-12);
  EXPECT_NEAR(enclosed_volume(s), 1.0, 1e-12);
  for (Triangle& t : s.triangles) std::swap(t[1], t[2]);
  r = check_surface(s, "inside_out");
  EXPECT_EQ(r.flipped_triangles, 12);
  EXPECT_NEAR(enclosed_volume(s), 1.0, 1e-12);
  EXPECT_EQ(r.genus, 0);
}

}  // namespace
}  // namespace mrsim::test
