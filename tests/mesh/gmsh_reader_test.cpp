// gmsh reader: element-type policy, node tags, binary byte order, and rejection of bad files.
#include <gmsh.h>
#include <gtest/gtest.h>

#include "mesh/box_mesh.hpp"
#include "mesh/gmsh_element_types.hpp"
#include "mesh_test_support.hpp"

namespace mrsim::test {
namespace {

// MSH 2.2 ASCII with the unit tet's nodes (tags 1-4) and the given element lines.
std::string msh22(const std::string& elements, int count, const std::string& extra_sections = "") {
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" + extra_sections +
         "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n$Elements\n" + std::to_string(count) + "\n" +
         elements + "$EndElements\n";
}

TEST(GmshReader, SkipsPointsLinesTrianglesAndUnknownSections) {
  ScratchDir dir;
  const std::string physical = "$PhysicalNames\n1\n3 1 \"body\"\n$EndPhysicalNames\n$Comments\nanything $Nodes\n$EndComments\n";
  write_file(dir / "m.msh", msh22("1 15 2 0 1 1\n2 1 2 0 1 1 2\n3 2 2 0 1 1 2 3\n4 4 2 1 1 1 2 3 4\n", 4, physical));
  MeshReadReport report;
  const TetMesh m = read_tet_mesh(dir / "m.msh", LengthUnit::Metre, &report);
  ASSERT_EQ(m.tets.size(), 1u);
  EXPECT_EQ(m.tets[0], (Tet{0, 1, 2, 3}));
  EXPECT_EQ(report.notes, (std::vector<std::string>{"ignored 1 lines", "ignored 1 points", "ignored 1 triangles"}));
}

TEST(GmshReader, RejectsHexahedra) {
  ScratchDir dir;
  write_file(dir / "hex.msh", msh22("1 5 2 1 1 1 2 3 4 1 2 3 4\n", 1));
  expect_mesh_error(dir / "hex.msh", {"element 1", "hexahedra (gmsh element type 5) are not supported"});
}

TEST(GmshReader, RejectsSecondOrderTetrahedra) {
  ScratchDir dir;
  write_file(dir / "tet10.msh", msh22("7 11 2 1 1 1 2 3 4 1 2 3 4 1 2\n", 1));
  expect_mesh_error(dir / "tet10.msh", {"element 7", "second-order tetrahedra (gmsh element type 11) are not supported; "
                                        "export linear elements"});
}

TEST(GmshReader, RejectsPrismsPyramidsAndUnknownTypes) {
  ScratchDir dir;
  write_file(dir / "prism.msh", msh22("1 6 0 1 2 3 4 1 2\n", 1));
  expect_mesh_error(dir / "prism.msh", {"prisms (gmsh element type 6)"});
  write_file(dir / "pyramid.msh", msh22("1 7 0 1 2 3 4 1\n", 1));
  expect_mesh_error(dir / "pyramid.msh", {"pyramids (gmsh element type 7)"});
  write_file(dir / "unknown.msh", msh22("1 42 0 1 2 3 4\n", 1));
  expect_mesh_error(dir / "unknown.msh", {"gmsh element type 42 is not supported"});
}

TEST(GmshReader, RejectsLegacyMsh1) {
  ScratchDir dir;
  write_file(dir / "v1.msh", "$NOD\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$ENDNOD\n$ELM\n1\n1 4 1 1 4 1 2 3 4\n$ENDELM\n");
  expect_mesh_error(dir / "v1.msh", {"legacy gmsh MSH 1", "gmsh FILE -save -format msh41 -o NEW.msh"});
}

TEST(GmshReader, RejectsMsh40AndNonGmshFiles) {
  ScratchDir dir;
  write_file(dir / "v40.msh", "$MeshFormat\n4 0 8\n$EndMeshFormat\n");
  expect_mesh_error(dir / "v40.msh", {"gmsh MSH version 4 is not supported", "4.1 or 2.2"});
  write_file(dir / "text.msh", "solid cube\nfacet normal 0 0 1\n");
  expect_mesh_error(dir / "text.msh", {"not a gmsh mesh file"});
}

TEST(GmshReader, ElementsMustReferToDefinedNodes) {
  ScratchDir dir;
  write_file(dir / "m.msh", msh22("1 4 0 1 2 3 99\n", 1));
  expect_mesh_error(dir / "m.msh", {"element 1 refers to node 99, which is not defined in $Nodes"});
}

TEST(GmshReader, DuplicateNodeTagsAreRejected) {
  ScratchDir dir;
  write_file(dir / "m.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n2 0 1 0\n4 0 0 1\n"
                            "$EndNodes\n$Elements\n1\n1 4 0 1 2 2 4\n$EndElements\n");
  expect_mesh_error(dir / "m.msh", {"node tag 2 is defined twice"});
}

// Sparse, huge tags take the hash-map path of NodeTagMap; the section order does not matter.
TEST(GmshReader, SparseTagsAndElementsBeforeNodes) {
  ScratchDir dir;
  write_file(dir / "m.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Elements\n1\n5 4 0 7 123456789012 3 99\n"
                            "$EndElements\n$Nodes\n4\n99 0 0 1\n7 0 0 0\n3 0 1 0\n123456789012 1 0 0\n$EndNodes\n");
  MeshReadReport report;
  const TetMesh m = read_tet_mesh(dir / "m.msh", LengthUnit::Metre, &report);
  ASSERT_EQ(m.points.size(), 4u);
  // File order is kept: 99, 7, 3, 123456789012 -> tet (7, 1234.., 3, 99) = (1, 3, 2, 0).
  EXPECT_EQ(m.points[0], Vec3(0, 0, 1));
  EXPECT_EQ(m.tets[0], (Tet{1, 3, 2, 0}));
  EXPECT_EQ(report.reoriented_tets, 0);
}

TEST(GmshReader, MissingSectionsAreReported) {
  ScratchDir dir;
  write_file(dir / "m.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n");
  expect_mesh_error(dir / "m.msh", {"has no $Elements section"});
  write_file(dir / "n.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n");
  expect_mesh_error(dir / "n.msh", {"line 5", "announces 2 nodes", "truncated"});
  write_file(dir / "e.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n1\n1 4 0 1 1 1 1\n");
  expect_mesh_error(dir / "e.msh", {"line 11", "unexpected end of file while reading $EndElements"});
  write_file(dir / "s.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n3 1 \"x\"\n");
  expect_mesh_error(dir / "s.msh", {"section $PhysicalNames has no $EndPhysicalNames"});
}

TEST(GmshReader, LyingCountsAreRejectedBeforeAllocating) {
  ScratchDir dir;
  write_file(dir / "nodes.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2000000000\n1 0 0 0\n$EndNodes\n");
  expect_mesh_error(dir / "nodes.msh", {"announces 2000000000 nodes, but only", "bytes remain"});
  write_file(dir / "huge.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n99999999999999\n");
  expect_mesh_error(dir / "huge.msh", {"the number of nodes is 99999999999999"});
  // Binary 4.1: patch numNodes (second size_t after "$Nodes\n") to a huge value.
  std::string bin = read_file(fixture("box_msh41_binary.msh"));
  const auto at = bin.find("$Nodes\n") + 7 + 8;
  const std::uint64_t lie = 1'000'000'000;
  std::memcpy(bin.data() + at, &lie, 8);
  write_file(dir / "lie41.msh", bin);
  expect_mesh_error(dir / "lie41.msh", {"announces 1000000000 nodes", "count is wrong or the file is truncated"});
}

TEST(GmshReader, BigEndianBinaryIsRead) {
  ScratchDir dir;
  const TetMesh box = make_box_mesh(Vec3(0, 0, 0), Vec3(0.3, 0.2, 0.1), 2, 2, 1);
  write_file(dir / "le.msh", msh22_binary(box, false));
  write_file(dir / "be.msh", msh22_binary(box, true));
  const TetMesh le = read_tet_mesh(dir / "le.msh", LengthUnit::Metre);
  const TetMesh be = read_tet_mesh(dir / "be.msh", LengthUnit::Metre);
  EXPECT_TRUE(le.points == box.points);
  EXPECT_TRUE(le.tets == box.tets);
  EXPECT_TRUE(be.points == box.points);
  EXPECT_TRUE(be.tets == box.tets);
}

TEST(GmshReader, BadEndiannessMarkerIsRejected) {
  ScratchDir dir;
  std::string bin = msh22_binary(make_box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), 1, 1, 1), false);
  bin[bin.find("2.2 1 8\n") + 8] = 7;
  write_file(dir / "m.msh", bin);
  expect_mesh_error(dir / "m.msh", {"endianness marker is 7"});
}

TEST(GmshReader, TruncatedBinaryFilesAreRejected) {
  ScratchDir dir;
  for (const char* name : {"box_msh22_binary.msh", "box_msh41_binary.msh"}) {
    const std::string bytes = read_file(fixture(name));
    // Inside the node coordinates: the node count no longer fits, reported at a byte offset.
    write_file(dir / "cut.msh", bytes.substr(0, bytes.find("$Nodes") + 200));
    expect_mesh_error(dir / "cut.msh", {"byte ", "announces 36 nodes", "truncated"});
    // Inside the binary endianness marker.
    write_file(dir / "cut.msh", bytes.substr(0, bytes.find(" 8\n") + 4));
    expect_mesh_error(dir / "cut.msh", {"unexpected end of file while reading the binary endianness marker"});
    // Just before $EndElements.
    write_file(dir / "cut.msh", bytes.substr(0, bytes.find("$EndElements") - 3));
    expect_mesh_error(dir / "cut.msh", {"truncated"});
  }
}

// A mesh generated by gmsh from geometry: nodes on curves and surfaces carry parametric
// coordinates when saved with Mesh.SaveParametric (1 or 2 extra values per node), and every
// entity is a separate block holding points, lines, triangles and tets.
TEST(GmshReader, GmshGeneratedMeshWithParametricNodes) {
  ScratchDir dir;
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("cube");
  gmsh::model::occ::addBox(0, 0, 0, 0.1, 0.2, 0.3);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.08);
  gmsh::model::mesh::generate(3);
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::option::setNumber("Mesh.SaveAll", 1);
  for (int binary : {0, 1}) {
    gmsh::option::setNumber("Mesh.Binary", binary);
    gmsh::option::setNumber("Mesh.SaveParametric", 0);
    gmsh::write((dir / ("plain" + std::to_string(binary) + ".msh")).string());
    gmsh::option::setNumber("Mesh.SaveParametric", 1);
    gmsh::write((dir / ("param" + std::to_string(binary) + ".msh")).string());
  }
  gmsh::finalize();

  // Same encoding on both sides: gmsh's ASCII (%.16g) does not round-trip every double.
  for (const std::string binary : {"0", "1"}) {
    MeshReadReport report;
    const TetMesh plain = read_tet_mesh(dir / ("plain" + binary + ".msh"), LengthUnit::Metre, &report);
    EXPECT_GT(plain.tets.size(), 10u);
    EXPECT_NEAR(total_volume(plain), 0.1 * 0.2 * 0.3, 1e-12);
    EXPECT_EQ(report.notes.size(), 3u);  // points, lines, triangles
    const TetMesh param = read_tet_mesh(dir / ("param" + binary + ".msh"), LengthUnit::Metre);
    EXPECT_TRUE(param.points == plain.points) << "binary " << binary;
    EXPECT_TRUE(param.tets == plain.tets) << "binary " << binary;
  }
  // The parametric files really hold the extra values (4 numbers on curve node lines).
  EXPECT_NE(read_file(dir / "param0.msh").find("\n1 1 1 "), std::string::npos);
}

// Our table of element types must agree with gmsh's own (node count and dimension).
TEST(GmshReader, ElementTableMatchesGmsh) {
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  std::vector<int> types;
  for (int t = 1; t <= 31; ++t) types.push_back(t);
  types.push_back(92);
  types.push_back(93);
  for (int t : types) {
#ifdef __SANITIZE_ADDRESS__
    // libgmsh 4.8 frees its prism face closures with delete instead of delete[]
    // (ClosureGen::getFaceClosurePrism), which AddressSanitizer aborts on.
    if (t == 6 || t == 13 || t == 18) continue;
#endif
    const GmshElementType* ours = find_gmsh_element_type(t);
    ASSERT_NE(ours, nullptr) << t;
    std::string name;
    int dim = 0, order = 0, nodes = 0, primary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(t, name, dim, order, nodes, local, primary);
    EXPECT_EQ(ours->nodes, nodes) << "type " << t << " " << name;
    EXPECT_EQ(ours->dim, dim) << "type " << t << " " << name;
  }
  gmsh::finalize();
}

}  // namespace
}  // namespace mrsim::test
