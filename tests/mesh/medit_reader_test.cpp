// Medit .mesh reader: free-form keywords, skipped sections, and rejections.
#include <gtest/gtest.h>

#include "mesh_test_support.hpp"

namespace mrsim::test {
namespace {

TEST(MeditReader, KeywordsAreCaseInsensitiveAndCommentsAndExtraSectionsAreSkipped) {
  ScratchDir dir;
  write_file(dir / "m.mesh",
             "# written by hand\nmeshversionformatted 1\n\nDIMENSION\n3\n"
             "Vertices 5  # four corners and an apex\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n+1 1.0E+0 1e0 2\n"
             "Edges\n1\n1 2 0\nCorners\n2\n1 2\nRidges 1 1\n"
             "Triangles\n2\n1 2 3 0\n1 2 4 0\n"
             "Normals\n1\n0 0 1\nNormalAtVertices\n1\n1 1\n"
             "tetrahedra\n2\n1 2 3 4 0\n2 5 3 4 0\nEnd\n");
  MeshReadReport report;
  const TetMesh m = read_tet_mesh(dir / "m.mesh", LengthUnit::Metre, &report);
  ASSERT_EQ(m.points.size(), 5u);
  ASSERT_EQ(m.tets.size(), 2u);
  EXPECT_EQ(m.tets[0], (Tet{0, 1, 2, 3}));
  EXPECT_EQ(m.points[4], Vec3(1, 1, 1));
  EXPECT_EQ(report.notes, (std::vector<std::string>{"ignored 1 edges", "ignored 2 triangles"}));
}

TEST(MeditReader, BinaryMeshbIsRejected) {
  ScratchDir dir;
  std::string meshb;
  put<std::int32_t>(meshb, 1);
  put<std::int32_t>(meshb, 2);
  meshb += std::string(32, '\0');
  write_file(dir / "m.meshb", meshb);
  expect_mesh_error(dir / "m.meshb", {"binary Medit files (.meshb) are not supported", "meshio convert"});
  write_file(dir / "disguised.mesh", meshb);
  expect_mesh_error(dir / "disguised.mesh", {"binary Medit"});
}

TEST(MeditReader, OtherVolumeCellsAreRejected) {
  ScratchDir dir;
  const std::string head = "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";
  write_file(dir / "hex.mesh", head + "Hexahedra\n1\n1 2 3 4 1 2 3 4 0\nEnd\n");
  expect_mesh_error(dir / "hex.mesh", {"Hexahedra are not supported"});
  write_file(dir / "p2.mesh", head + "TetrahedraP2\n1\n1 2 3 4 1 2 3 4 1 2 0\nEnd\n");
  expect_mesh_error(dir / "p2.mesh", {"TetrahedraP2", "export linear (4-vertex) tetrahedra"});
  write_file(dir / "prism.mesh", head + "Prisms\n1\n1 2 3 4 1 2 0\nEnd\n");
  expect_mesh_error(dir / "prism.mesh", {"Prisms are not supported"});
}

TEST(MeditReader, OutOfRangeVertexIsRejected) {
  ScratchDir dir;
  write_file(dir / "m.mesh", medit_text(unit_tet_points(), {{1, 2, 3, 9}}));
  expect_mesh_error(dir / "m.mesh", {"tetrahedron 1 refers to vertex 9, but Vertices holds 4 vertices"});
  write_file(dir / "zero.mesh", medit_text(unit_tet_points(), {{0, 1, 2, 3}}));
  expect_mesh_error(dir / "zero.mesh", {"refers to vertex 0", "numbered from 1"});
}

TEST(MeditReader, MalformedFilesAreRejected) {
  ScratchDir dir;
  write_file(dir / "a.mesh", "Dimension 3\n");
  expect_mesh_error(dir / "a.mesh", {"not a Medit mesh file"});
  write_file(dir / "b.mesh", "MeshVersionFormatted 2\nDimension 2\n");
  expect_mesh_error(dir / "b.mesh", {"line 2", "2-D mesh"});
  write_file(dir / "c.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n2000000000\n0 0 0 0\n");
  expect_mesh_error(dir / "c.mesh", {"announces 2000000000 vertices"});
  write_file(dir / "d.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n2\n0 0 0 0\n1 0 zero 0\n");
  expect_mesh_error(dir / "d.mesh", {"line 6", "expected a vertex coordinate (a number), found 'zero'"});
  write_file(dir / "e.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
                             "Tetrahedra\n1\n1 2 3");
  expect_mesh_error(dir / "e.mesh", {"line 10", "truncated"});
  write_file(dir / "h.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
                             "Tetrahedra\n1\n1 2 3 4   \n");
  expect_mesh_error(dir / "h.mesh", {"unexpected end of file while reading a tetrahedron reference"});
  write_file(dir / "f.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0 0 0\nVertices\n1\n0 0 0 0\n");
  expect_mesh_error(dir / "f.mesh", {"a second Vertices section"});
  write_file(dir / "g.mesh", "MeshVersionFormatted 9\n");
  expect_mesh_error(dir / "g.mesh", {"MeshVersionFormatted value is 9"});
}

}  // namespace
}  // namespace mrsim::test
