// Real meshes from /work/shared/data (see its SOURCES.md); skipped when that folder is absent.
// liver_cgal_h14.* and liver_cgal_h10.* hold ONE mesh each, written by meshio in every
// format: the readers must give bitwise equal points and identical tets.
#include <gmsh.h>
#include <gtest/gtest.h>

#include "mesh_test_support.hpp"

namespace mrsim::test {
namespace {

fs::path liver(const std::string& name) { return shared_data() / "liver_cgal" / name; }

void expect_identical(const TetMesh& a, const TetMesh& b, const std::string& what) {
  ASSERT_EQ(a.points.size(), b.points.size()) << what;
  ASSERT_EQ(a.tets.size(), b.tets.size()) << what;
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.points.size(); ++i)
    for (int c = 0; c < 3; ++c) differing += a.points[i][c] != b.points[i][c];  // bitwise
  EXPECT_EQ(differing, 0u) << what;
  EXPECT_TRUE(a.tets == b.tets) << what;
}

// gmsh's C++ API for one test; quiet.
struct GmshSession {
  GmshSession() {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
  }
  ~GmshSession() { gmsh::finalize(); }
};

struct LiverCase {
  const char* stem;
  std::size_t points, tets;
};

class Liver : public ::testing::TestWithParam<LiverCase> {};

TEST_P(Liver, AllFormatsGiveTheSameMesh) {
  MRSIM_REQUIRE_SHARED_DATA();
  const std::string stem = GetParam().stem;
  const TetMesh msh = read_tet_mesh(liver(stem + ".msh"), LengthUnit::Millimetre);
  ASSERT_EQ(msh.points.size(), GetParam().points);
  ASSERT_EQ(msh.tets.size(), GetParam().tets);
  for (const char* ext : {".vtu", ".mesh", ".node", ".ele"})
    expect_identical(read_tet_mesh(liver(stem + ext), LengthUnit::Millimetre), msh, stem + ext);
  // ~1.74e6 mm^3 = 1.74e-3 m^3 (SOURCES.md).
  EXPECT_NEAR(total_volume(msh), 1.74e-3, 0.05e-3);
}

// The ascii .vtu rounds coordinates to about 5e-10 mm (SOURCES.md), so it is compared with a
// 1e-9 mm tolerance, in file units (LengthUnit::Metre applies no scaling).
TEST_P(Liver, AsciiVtuMatchesWithin1e9mm) {
  MRSIM_REQUIRE_SHARED_DATA();
  const std::string stem = GetParam().stem;
  const TetMesh exact = read_tet_mesh(liver(stem + ".msh"), LengthUnit::Metre);
  const TetMesh ascii = read_tet_mesh(liver(stem + "_ascii.vtu"), LengthUnit::Metre);
  ASSERT_EQ(ascii.points.size(), exact.points.size());
  double worst = 0;
  for (std::size_t i = 0; i < exact.points.size(); ++i)
    worst = std::max(worst, (ascii.points[i] - exact.points[i]).cwiseAbs().maxCoeff());
  EXPECT_LE(worst, 1e-9);
  EXPECT_GT(worst, 0.0) << "the ascii file was expected to be rounded";
  EXPECT_TRUE(ascii.tets == exact.tets);
}

TEST_P(Liver, MillimetresBecomeMetresByFactor1e3) {
  MRSIM_REQUIRE_SHARED_DATA();
  const fs::path path = liver(std::string(GetParam().stem) + ".vtu");
  const TetMesh file_units = read_tet_mesh(path, LengthUnit::Metre);
  const TetMesh metres = read_tet_mesh(path, LengthUnit::Millimetre);
  for (std::size_t i = 0; i < metres.points.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(metres.points[i][c], file_units.points[i][c] * 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Cgal, Liver,
                         ::testing::Values(LiverCase{"liver_cgal_h14", 1193, 4620},
                                           LiverCase{"liver_cgal_h10", 2439, 10528}),
                         [](const auto& info) { return std::string(info.param.stem); });

// gmsh itself rewrites the liver as binary MSH 4.1 and 2.2: both must read back unchanged.
TEST(SharedMeshes, GmshBinaryRewritesOfTheLiverReadBackEqual) {
  MRSIM_REQUIRE_SHARED_DATA();
  ScratchDir scratch;
  const fs::path source = liver("liver_cgal_h14.msh");
  const TetMesh original = read_tet_mesh(source, LengthUnit::Millimetre);
  {
    GmshSession gmsh_session;
    gmsh::open(source.string());
    gmsh::option::setNumber("Mesh.Binary", 1);
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::write((scratch / "liver41.msh").string());
    gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
    gmsh::write((scratch / "liver22.msh").string());
  }
  MeshReadReport r41, r22;
  expect_identical(read_tet_mesh(scratch / "liver41.msh", LengthUnit::Millimetre, &r41), original, "4.1 binary");
  expect_identical(read_tet_mesh(scratch / "liver22.msh", LengthUnit::Millimetre, &r22), original, "2.2 binary");
  EXPECT_EQ(r41.format, "gmsh-4.1-binary");
  EXPECT_EQ(r22.format, "gmsh-2.2-binary");
}

TEST(SharedMeshes, CgalSphereMedit) {
  MRSIM_REQUIRE_SHARED_DATA();
  MeshReadReport report;
  const TetMesh m = read_tet_mesh(shared_data() / "cgal" / "sphere_tets.mesh", LengthUnit::Metre, &report);
  EXPECT_EQ(m.points.size(), 757u);
  EXPECT_EQ(m.tets.size(), 3586u);
  EXPECT_EQ(report.reoriented_tets, 0);  // SOURCES.md: every tet is positive
  EXPECT_EQ(report.format, "medit");
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_EQ(report.notes[0], "ignored 694 triangles");
}

TEST(SharedMeshes, TetgenOutputOfTheLiverSurface) {
  MRSIM_REQUIRE_SHARED_DATA();
  MeshReadReport report;
  const TetMesh m = read_tet_mesh(liver("liver_cgal_h14_tetgen.1.node"), LengthUnit::Millimetre, &report);
  EXPECT_EQ(m.points.size(), 4236u);
  EXPECT_EQ(m.tets.size(), 16961u);
  EXPECT_EQ(report.reoriented_tets, 0);
  EXPECT_NEAR(total_volume(m), 1.74e-3, 0.05e-3);
}

TEST(SharedMeshes, SurfaceOnlyVtuIsRejected) {
  MRSIM_REQUIRE_SHARED_DATA();
  expect_mesh_error(shared_data() / "cgal" / "sphere_surface.vtu",
                    {"contains no tetrahedra (only 320 triangles): a volume mesh is needed"});
}

TEST(SharedMeshes, SurfaceFilesPointToMrsimMesh) {
  MRSIM_REQUIRE_SHARED_DATA();
  for (const fs::path& p : {shared_data() / "cgal" / "sphere.off", shared_data() / "sofa" / "Bunny.stl",
                            shared_data() / "sofa" / "liver.obj"})
    expect_mesh_error(p, {"is a surface mesh", "mrsim mesh"});
}

// MSH 1 is rejected with advice to re-save it with gmsh; following that advice works.
TEST(SharedMeshes, LegacyMsh1IsRejectedAndGmshConversionWorks) {
  MRSIM_REQUIRE_SHARED_DATA();
  const fs::path legacy = shared_data() / "sofa" / "liver.msh";
  expect_mesh_error(legacy, {"legacy gmsh MSH 1", "$NOD/$ELM", "save it as MSH 4.1 or 2.2", "-format msh41"});
  ScratchDir scratch;
  {
    GmshSession gmsh_session;
    gmsh::open(legacy.string());
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::write((scratch / "liver41.msh").string());
  }
  const TetMesh m = read_tet_mesh(scratch / "liver41.msh", LengthUnit::Metre);
  EXPECT_EQ(m.points.size(), 181u);
  EXPECT_EQ(m.tets.size(), 596u);
  EXPECT_NEAR(total_volume(m), 36.56, 0.01);  // SOURCES.md
}

}  // namespace
}  // namespace mrsim::test
