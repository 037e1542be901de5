// One small box mesh (36 points, 72 tets, 64 boundary triangles) written by gmsh, VTK and
// by hand for TetGen (tests/data/mesh/README.md): every format must load to the very same
// points (bitwise) and tets (same order).
#include <gtest/gtest.h>

#include "mesh_test_support.hpp"

namespace mrsim::test {
namespace {

struct FormatCase {
  const char* file;
  const char* format;
};

const FormatCase kCases[] = {
    {"box_msh22_ascii.msh", "gmsh-2.2-ascii"},   {"box_msh22_binary.msh", "gmsh-2.2-binary"},
    {"box_msh41_ascii.msh", "gmsh-4.1-ascii"},   {"box_msh41_binary.msh", "gmsh-4.1-binary"},
    {"box_appended_zlib.vtu", "vtu"},            {"box_appended_zlib_bigendian.vtu", "vtu"},
    {"box_appended_base64.vtu", "vtu"},
    {"box_inline_zlib.vtu", "vtu"},              {"box_ascii.vtu", "vtu"},
    {"box_medit.mesh", "medit"},
    {"box_tetgen_base0.node", "tetgen"},         {"box_tetgen_base1.ele", "tetgen"},
};

TetMesh reference() { return read_tet_mesh(fixture("box_msh41_ascii.msh"), LengthUnit::Metre); }

TEST(FixtureFormats, ReferenceIsTheBox) {
  MeshReadReport report;
  const TetMesh m = read_tet_mesh(fixture("box_msh41_ascii.msh"), LengthUnit::Metre, &report);
  ASSERT_EQ(m.points.size(), 36u);
  ASSERT_EQ(m.tets.size(), 72u);
  // Box [-0.05, 0.07] x [0.01, 0.13] x [0.02, 0.10].
  EXPECT_NEAR(total_volume(m), 0.12 * 0.12 * 0.08, 1e-15);
  EXPECT_EQ(report.reoriented_tets, 0);
  EXPECT_EQ(report.removed_vertices, 0);
  EXPECT_TRUE(report.warnings.empty());
  ASSERT_EQ(report.kept_vertices.size(), 36u);
  EXPECT_EQ(report.kept_vertices[35], 35);
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_EQ(report.notes[0], "ignored 64 triangles");
}

// One test over all files (not one per file): each test is a process under ctest, and
// loading gmsh and VTK costs ~0.1 s per process. SCOPED_TRACE names the file on failure.
TEST(FixtureFormats, EveryFormatLoadsIdenticalPointsAndTets) {
  const TetMesh ref = reference();
  for (const FormatCase& c : kCases) {
    SCOPED_TRACE(c.file);
    MeshReadReport report;
    const TetMesh m = read_tet_mesh(fixture(c.file), LengthUnit::Metre, &report);
    EXPECT_EQ(report.format, c.format);
    ASSERT_EQ(m.points.size(), ref.points.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < m.points.size(); ++i)
      for (int a = 0; a < 3; ++a) differing += m.points[i][a] != ref.points[i][a];  // bitwise: no tolerance
    EXPECT_EQ(differing, 0u);
    EXPECT_TRUE(m.tets == ref.tets);
    EXPECT_TRUE(report.warnings.empty());
  }
}

TEST(FixtureFormats, MillimetresAreScaledByExactly1e3) {
  const TetMesh m = read_tet_mesh(fixture("box_msh41_binary.msh"), LengthUnit::Metre);
  const TetMesh mm = read_tet_mesh(fixture("box_msh41_binary.msh"), LengthUnit::Millimetre);
  EXPECT_EQ(metres_per(LengthUnit::Millimetre), 1e-3);
  EXPECT_EQ(metres_per(LengthUnit::Metre), 1.0);
  ASSERT_EQ(m.points.size(), mm.points.size());
  for (std::size_t i = 0; i < m.points.size(); ++i)
    for (int a = 0; a < 3; ++a) EXPECT_EQ(mm.points[i][a], m.points[i][a] * 1e-3);
  EXPECT_EQ(mm.tets, m.tets);
}

TEST(FixtureFormats, TetgenAcceptsEitherFileOfThePair) {
  const TetMesh from_node = read_tet_mesh(fixture("box_tetgen_base1.node"), LengthUnit::Metre);
  const TetMesh from_ele = read_tet_mesh(fixture("box_tetgen_base1.ele"), LengthUnit::Metre);
  EXPECT_EQ(from_node.points, from_ele.points);
  EXPECT_EQ(from_node.tets, from_ele.tets);
}

}  // namespace
}  // namespace mrsim::test
