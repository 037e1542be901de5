// The checks run after every reader (mesh_check.cpp), the unit conversion, and the dispatch
// on file extensions (mesh_reader.cpp).
#include <gtest/gtest.h>

#include "mesh/box_mesh.hpp"
#include "mesh/mesh_check.hpp"
#include "mesh_test_support.hpp"

namespace mrsim::test {
namespace {

TEST(MeshCheck, NonFiniteCoordinateNamesTheVertex) {
  ScratchDir dir;
  auto points = unit_tet_points();
  points[2][1] = "nan";
  write_file(dir / "m.mesh", medit_text(points, {{1, 2, 3, 4}}));
  expect_mesh_error(dir / "m.mesh", {"vertex 3 has a non-finite coordinate (0, nan, 0)"});
  points[2][1] = "-inf";
  write_file(dir / "m.mesh", medit_text(points, {{1, 2, 3, 4}}));
  expect_mesh_error(dir / "m.mesh", {"vertex 3 has a non-finite coordinate (0, -inf, 0)"});
}

TEST(MeshCheck, RepeatedVertexInATetIsRejected) {
  ScratchDir dir;
  write_file(dir / "m.mesh", medit_text(unit_tet_points(), {{1, 2, 3, 4}, {1, 2, 2, 4}}));
  expect_mesh_error(dir / "m.mesh", {"tetrahedron 2 uses vertex 2 twice (vertices 1, 2, 2, 4)"});
}

TEST(MeshCheck, ZeroVolumeTetIsRejectedWithItsQuality) {
  ScratchDir dir;
  auto points = unit_tet_points();
  points.push_back({"1", "1", "0"});  // coplanar with vertices 1, 2, 3
  write_file(dir / "m.mesh", medit_text(points, {{1, 2, 3, 4}, {1, 2, 5, 3}}));
  expect_mesh_error(dir / "m.mesh", {"tetrahedron 2 (vertices 1, 2, 5, 3) is degenerate", "= 0 < 1e-08"});
}

TEST(MeshCheck, NearlyFlatTetIsRejectedButTinyWellShapedTetIsNot) {
  ScratchDir dir;
  // Apex 1e-9 above a right triangle of unit legs: |6V| = 1e-9, longest edge sqrt(2), so the
  // quality is 1e-9 / 2^1.5 = 3.54e-10.
  write_file(dir / "flat.mesh", medit_text({{"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}, {"0.3", "0.3", "1e-9"}},
                                           {{1, 2, 3, 4}}));
  expect_mesh_error(dir / "flat.mesh", {"is degenerate", "quality |6V|/(longest edge)^3 = 3.54e-10"});
  // The same shape as the unit tet, one micrometre across, in millimetres: the test is
  // scale-free, so it is accepted.
  write_file(dir / "tiny.mesh", medit_text({{"0", "0", "0"}, {"1e-3", "0", "0"}, {"0", "1e-3", "0"}, {"0", "0", "1e-3"}},
                                           {{1, 2, 3, 4}}));
  const TetMesh m = read_tet_mesh(dir / "tiny.mesh", LengthUnit::Millimetre);
  EXPECT_NEAR(total_volume(m), 1e-18 / 6, 1e-30);
}

TEST(MeshCheck, DegenerateCountIsGiven) {
  ScratchDir dir;
  write_file(dir / "m.mesh", medit_text({{"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}, {"1", "1", "0"}},
                                        {{1, 2, 3, 4}, {2, 1, 3, 4}, {4, 3, 2, 1}}));
  expect_mesh_error(dir / "m.mesh", {"tetrahedron 1 (", "3 tetrahedra are degenerate in total"});
}

TEST(MeshCheck, InvertedTetsAreReorientedWithOneWarning) {
  ScratchDir dir;
  TetMesh box = make_box_mesh(Vec3(0, 0, 0), Vec3(1, 2, 3), 2, 2, 2);
  const double volume = total_volume(box);
  for (std::size_t k = 0; k < box.tets.size(); k += 3) std::swap(box.tets[k][0], box.tets[k][1]);  // 16 of 48
  write_file(dir / "m.msh", msh22_binary(box, false));
  MeshReadReport report;
  const TetMesh m = read_tet_mesh(dir / "m.msh", LengthUnit::Metre, &report);
  EXPECT_EQ(report.reoriented_tets, 16);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("16 of 48 elements had a negative volume (inverted) and were reoriented"),
            std::string::npos)
      << report.warnings[0];
  EXPECT_EQ(report.warnings[0].rfind((dir / "m.msh").string(), 0), 0u);
  for (const Tet& t : m.tets) EXPECT_GT(signed_volume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]), 0);
  EXPECT_NEAR(total_volume(m), volume, 1e-12);
  // The reoriented tets keep their vertices.
  for (std::size_t k = 0; k < m.tets.size(); ++k) {
    Tet a = m.tets[k], b = box.tets[k];
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b);
  }
}

TEST(MeshCheck, UnreferencedVerticesAreRemovedAndReported) {
  ScratchDir dir;
  // Vertices 1 and 4 (1-based) are used by no tet; the tet uses 2, 3, 5, 6.
  write_file(dir / "m.mesh", medit_text({{"9", "9", "9"}, {"0", "0", "0"}, {"1", "0", "0"}, {"8", "8", "8"},
                                         {"0", "1", "0"}, {"0", "0", "1"}},
                                        {{2, 3, 5, 6}}));
  MeshReadReport report;
  const TetMesh m = read_tet_mesh(dir / "m.mesh", LengthUnit::Metre, &report);
  ASSERT_EQ(m.points.size(), 4u);
  EXPECT_EQ(m.tets[0], (Tet{0, 1, 2, 3}));
  EXPECT_EQ(m.points[3], Vec3(0, 0, 1));
  EXPECT_EQ(report.removed_vertices, 2);
  EXPECT_EQ(report.kept_vertices, (std::vector<int>{1, 2, 4, 5}));
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("removed 2 vertices used by no tetrahedron (vertices 1, 4)"), std::string::npos)
      << report.warnings[0];
}

TEST(MeshCheck, ManyUnreferencedVerticesListOnlyTheFirstFew) {
  ScratchDir dir;
  auto points = unit_tet_points();
  for (int i = 0; i < 8; ++i) points.push_back({"5", "5", std::to_string(i)});
  write_file(dir / "m.mesh", medit_text(points, {{1, 2, 3, 4}}));
  MeshReadReport report;
  read_tet_mesh(dir / "m.mesh", LengthUnit::Metre, &report);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("removed 8 vertices used by no tetrahedron (vertices 5, 6, 7, 8, 9, ...)"),
            std::string::npos)
      << report.warnings[0];
}

TEST(MeshCheck, EmptyMeshIsRejected) {
  ScratchDir dir;
  write_file(dir / "m.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n0\nTetrahedra\n0\nEnd\n");
  expect_mesh_error(dir / "m.mesh", {"contains no tetrahedra: a volume mesh is needed"});
}

// The range check repeated in mesh_check catches any reader that lets a bad index through.
TEST(MeshCheck, IndexOutOfRangeIsCaughtEvenAfterAReader) {
  RawMesh raw;
  raw.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  raw.point_ids = {0, 1, 2, 3};
  raw.tets = {Tet{0, 1, 2, 4}};
  raw.tet_ids = {12};
  raw.tet_noun = "cell";
  raw.point_noun = "point";
  const std::string message = input_error_of([&] { check_raw_mesh(raw, "x.vtu", 1.0, nullptr); });
  EXPECT_EQ(message, "x.vtu: cell 12 refers to point index 4 (0-based), but the file has 4 points");
}

TEST(MeshReader, UnknownExtensionListsTheSupportedOnes) {
  ScratchDir dir;
  write_file(dir / "m.xyz", "1 2 3\n");
  expect_mesh_error(dir / "m.xyz", {"unknown mesh file extension '.xyz'", ".msh", ".vtu", ".mesh", ".node/.ele"});
  write_file(dir / "m.vtk", "# vtk DataFile Version 3.0\n");
  expect_mesh_error(dir / "m.vtk", {"legacy VTK (.vtk) files are not supported", ".vtu"});
}

TEST(MeshReader, SurfaceFilesAreNamedAsSuch) {
  ScratchDir dir;
  for (const char* name : {"s.stl", "s.OBJ", "s.off", "s.ply"}) {
    write_file(dir / name, "solid\n");
    expect_mesh_error(dir / name, {"is a surface mesh", "`mrsim mesh SURFACE` builds tet meshes from surfaces"});
  }
}

TEST(MeshReader, MissingFileIsReported) {
  ScratchDir dir;
  for (const char* name : {"none.msh", "none.vtu", "none.mesh", "none.node", "none.xyz"})
    expect_mesh_error(dir / name, {"file not found"});
}

TEST(MeshReader, EmptyFilesAreReported) {
  ScratchDir dir;
  for (const char* name : {"e.msh", "e.vtu", "e.mesh"}) {
    write_file(dir / name, "");
    expect_mesh_error(dir / name, {"file is empty"});
  }
  write_file(dir / "e.node", "");
  write_file(dir / "e.ele", "1 4 0\n0 0 1 2 3\n");
  expect_mesh_error(dir / "e.ele", {"file is empty"}, dir / "e.node");
}

TEST(MeshReader, DirectoryIsNotAMesh) {
  ScratchDir dir;
  std::filesystem::create_directories(dir / "d.msh");
  expect_mesh_error(dir / "d.msh", {"not a regular file"});
}

}  // namespace
}  // namespace mrsim::test
