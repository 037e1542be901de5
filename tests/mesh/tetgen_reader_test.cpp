// TetGen .node/.ele reader: numbering base, sibling lookup, header consistency.
#include <gtest/gtest.h>

#include "mesh_test_support.hpp"

namespace mrsim::test {
namespace {

const char* kNodes0 = "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n";

TEST(TetgenReader, MissingSiblingIsReported) {
  ScratchDir dir;
  write_file(dir / "m.node", kNodes0);
  expect_mesh_error(dir / "m.node", {"needs both .node and .ele", "m.ele was not found"});
  write_file(dir / "n.ele", "1 4 0\n0 0 1 2 3\n");
  expect_mesh_error(dir / "n.ele", {"n.node was not found"});
}

TEST(TetgenReader, UpperCaseExtensionsFindTheirSibling) {
  ScratchDir dir;
  write_file(dir / "m.NODE", kNodes0);
  write_file(dir / "m.ELE", "1 4 0\n0 0 1 2 3\n");
  EXPECT_EQ(read_tet_mesh(dir / "m.NODE", LengthUnit::Metre).tets.size(), 1u);
}

TEST(TetgenReader, SecondOrderTetsAreRejected) {
  ScratchDir dir;
  write_file(dir / "m.node", kNodes0);
  write_file(dir / "m.ele", "1 10 0\n0 0 1 2 3 0 1 2 3 0 1\n");
  expect_mesh_error(dir / "m.node", {"line 1", "second-order tetrahedra (10 nodes) are not supported",
                                     "export linear elements"}, dir / "m.ele");
}

TEST(TetgenReader, OutOfRangeNodeIsRejected) {
  ScratchDir dir;
  write_file(dir / "m.node", kNodes0);
  write_file(dir / "m.ele", "1 4 0\n0 0 1 2 4\n");
  expect_mesh_error(dir / "m.ele", {"tetrahedron 0 refers to node 4, but the .node file holds nodes 0 to 3"});
  // 1-based: node 0 does not exist.
  write_file(dir / "o.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n");
  write_file(dir / "o.ele", "1 4 0\n1 0 1 2 3\n");
  expect_mesh_error(dir / "o.ele", {"refers to node 0, but the .node file holds nodes 1 to 4"});
}

TEST(TetgenReader, NodeNumberingMustStartAt0Or1AndBeConsecutive) {
  ScratchDir dir;
  write_file(dir / "m.ele", "1 4 0\n0 0 1 2 3\n");
  write_file(dir / "m.node", "4 3 0 0\n2 0 0 0\n3 1 0 0\n4 0 1 0\n5 0 0 1\n");
  expect_mesh_error(dir / "m.ele", {"first node index is 2"}, dir / "m.node");
  write_file(dir / "m.node", "4 3 0 0\n0 0 0 0\n1 1 0 0\n3 0 1 0\n4 0 0 1\n");
  expect_mesh_error(dir / "m.ele", {"line 4", "node index 3, expected 2"}, dir / "m.node");
}

TEST(TetgenReader, HeaderMustMatchTheLines) {
  ScratchDir dir;
  write_file(dir / "m.ele", "1 4 0\n0 0 1 2 3\n");
  // The header announces no attribute, but each line has one.
  write_file(dir / "m.node", "4 3 0 0\n0 0 0 0 7\n1 1 0 0 7\n2 0 1 0 7\n3 0 0 1 7\n");
  expect_mesh_error(dir / "m.ele", {"line 2", "unexpected extra value '7'"}, dir / "m.node");
  write_file(dir / "m.node", "4 2 0 0\n");
  expect_mesh_error(dir / "m.ele", {"dimension is 2"}, dir / "m.node");
  write_file(dir / "m.node", "2000000000 3 0 0\n0 0 0 0\n");
  expect_mesh_error(dir / "m.ele", {"announces 2000000000 nodes"}, dir / "m.node");
  write_file(dir / "m.node", "0 3 0 0\n");
  expect_mesh_error(dir / "m.ele", {"holds no nodes", ".poly"}, dir / "m.node");
}

TEST(TetgenReader, CommentsAttributesMarkersAndRegionsAreAccepted) {
  ScratchDir dir;
  write_file(dir / "m.node", "# nodes\n4 3 2 1 # header\n1 0 0 0 0.5 1e3 1\n2 1 0 0 0 0 0\n# between\n"
                             "3 0 1 0 0 0 1\n4 0 0 1 0 0 1  # last\n");
  write_file(dir / "m.ele", "1 4 1\n1 1 2 3 4 -2.5\n");
  const TetMesh m = read_tet_mesh(dir / "m.node", LengthUnit::Metre);
  ASSERT_EQ(m.tets.size(), 1u);
  EXPECT_EQ(m.tets[0], (Tet{0, 1, 2, 3}));
}

}  // namespace
}  // namespace mrsim::test
