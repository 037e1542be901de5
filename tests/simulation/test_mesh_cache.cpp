// A level's .vtu kept between runs (simulation/mesh_cache.hpp): a second read gives read_tet_mesh's
// mesh and report bit for bit (its warnings said again) without VTK; other bytes, another unit
// or another path are another key; a damaged record, or one whose tets leave the mesh, is said,
// ignored and read again; other formats and unreadable files go straight to read_tet_mesh.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "core/error.hpp"
#include "core/text_file.hpp"
#include "mesh/mesh_test_support.hpp"
#include "simulation/cache_folder.hpp"
#include "simulation/cached_payload.hpp"
#include "simulation/mesh_cache.hpp"
#include "simulation/result_cache.hpp"

using namespace mrsim;
using mrsim::test::ScratchDir;
using mrsim::test::write_file;

namespace {

// Two tets over six points: the second tet inverted, the sixth point used by none. Read, it
// warns twice (reoriented, removed).
std::string warned_vtu() {
  return "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "<UnstructuredGrid>\n<Piece NumberOfPoints=\"6\" NumberOfCells=\"2\">\n"
         "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"
         "0 0 0 1 0 0 0 1 0 0 0 1 1 1 1 5 5 5\n</DataArray>\n</Points>\n<Cells>\n"
         "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 2 1 3 4"
         "</DataArray>\n"
         "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4 8</DataArray>\n"
         "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10 10</DataArray>\n"
         "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

void expect_same(const TetMesh& a, const TetMesh& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  ASSERT_EQ(a.tets, b.tets);
  for (std::size_t i = 0; i < a.points.size(); ++i)
    EXPECT_EQ(std::memcmp(a.points[i].data(), b.points[i].data(), sizeof(double) * 3), 0) << i;
}

void expect_same(const MeshReadReport& a, const MeshReadReport& b) {
  EXPECT_EQ(a.format, b.format);
  EXPECT_EQ(a.reoriented_tets, b.reoriented_tets);
  EXPECT_EQ(a.removed_vertices, b.removed_vertices);
  EXPECT_EQ(a.kept_vertices, b.kept_vertices);
  EXPECT_EQ(a.warnings, b.warnings);
  EXPECT_EQ(a.notes, b.notes);
}


}  // namespace

TEST(MeshCache, ASecondReadIsTheFirstBitForBitWithItsWarnings) {
  CacheFolder folder("meshes");
  ScratchDir dir;
  const auto path = dir / "warned.vtu";
  write_file(path, warned_vtu());
  MeshReadReport direct;
  const TetMesh expected = read_tet_mesh(path, LengthUnit::Millimetre, &direct);
  ASSERT_EQ(direct.warnings.size(), 2u);
  bool reused = true;
  MeshReadReport first, second;
  expect_same(read_level_mesh(path, LengthUnit::Millimetre, &first, &reused), expected);
  EXPECT_FALSE(reused);
  ASSERT_EQ(folder.files("meshes").size(), 1u);
  expect_same(read_level_mesh(path, LengthUnit::Millimetre, &second, &reused), expected);
  EXPECT_TRUE(reused);
  expect_same(first, direct);
  expect_same(second, direct);
  // Without a report the warnings are printed, as read_tet_mesh prints them.
  ::testing::internal::CaptureStderr();
  read_level_mesh(path, LengthUnit::Millimetre, nullptr, &reused);
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_TRUE(reused);
  EXPECT_NE(said.find("were reoriented"), std::string::npos) << said;
  EXPECT_NE(said.find("used by no"), std::string::npos) << said;
}

TEST(MeshCache, OtherBytesAnotherUnitOrAnotherPathAreAnotherKey) {
  CacheFolder folder("meshes");
  ScratchDir dir;
  const auto path = dir / "m.vtu";
  write_file(path, warned_vtu());
  bool reused = true;
  MeshReadReport quiet;  // the warnings go here, not to the test's output
  read_level_mesh(path, LengthUnit::Metre, &quiet, &reused);
  // Points moved in the file: the mesh read again, with them.
  std::string moved = warned_vtu();
  moved.replace(moved.find("1 1 1 5"), 7, "1 1 2 5");
  write_file(path, moved);
  MeshReadReport report;
  const TetMesh m = read_level_mesh(path, LengthUnit::Metre, &report, &reused);
  EXPECT_FALSE(reused);
  EXPECT_EQ(m.points[4].z(), 2.0);
  const TetMesh mm = read_level_mesh(path, LengthUnit::Millimetre, &quiet, &reused);
  EXPECT_FALSE(reused);
  EXPECT_EQ(mm.points[4].z(), 2e-3);
  // A copy elsewhere: its warnings name it.
  const auto copy = dir / "copy.vtu";
  write_file(copy, moved);
  MeshReadReport copied;
  read_level_mesh(copy, LengthUnit::Metre, &copied, &reused);
  EXPECT_FALSE(reused);
  ASSERT_FALSE(copied.warnings.empty());
  EXPECT_EQ(copied.warnings[0].rfind(copy.string(), 0), 0u) << copied.warnings[0];
  EXPECT_EQ(folder.files("meshes").size(), 4u);
}

TEST(MeshCache, ADamagedRecordIsSaidIgnoredAndReadAgain) {
  CacheFolder folder("meshes");
  ScratchDir dir;
  const auto path = dir / "m.vtu";
  write_file(path, warned_vtu());
  MeshReadReport quiet;  // the warnings go here, not to the test's output
  const TetMesh expected = read_tet_mesh(path, LengthUnit::Metre, &quiet);
  read_level_mesh(path, LengthUnit::Metre, &quiet);
  ASSERT_EQ(folder.files("meshes").size(), 1u);
  const auto file = folder.files("meshes")[0];
  const std::string good = read_text_if_any(file);
  // The first point's x is the record's bytes 8..15 (after the points' count), the first
  // tet's first vertex bytes 16 + 5·24 + 8 on (after the tets' count).
  const std::size_t first_vertex = 8 + 5 * 24 + 8;
  struct Damage {
    const char* what;
    std::function<void()> apply;
    const char* said;
  };
  const std::vector<Damage> damages = {
      {"a flipped bit",
       [&] {
         std::string b = good;
         b[b.size() - 3] ^= 4;
         write_file(file, b);
       },
       "damaged"},
      {"a tet vertex out of the mesh",
       [&] {
         write_file(file, good);
         rewrite_payload(file, [&](std::string& p) {
           const int far = 99;
           std::memcpy(p.data() + first_vertex, &far, sizeof far);
         });
       },
       "a tet vertex out of the mesh"},
      {"a point that is not finite",
       [&] {
         write_file(file, good);
         rewrite_payload(file, [](std::string& p) {
           const double nan = std::numeric_limits<double>::quiet_NaN();
           std::memcpy(p.data() + 8, &nan, sizeof nan);
         });
       },
       "a point that is not finite"},
      {"an inverted tet",
       [&] {
         write_file(file, good);
         rewrite_payload(file, [&](std::string& p) {
           int t[4];
           std::memcpy(t, p.data() + first_vertex, sizeof t);
           std::swap(t[0], t[1]);
           std::memcpy(p.data() + first_vertex, t, sizeof t);
         });
       },
       "not positively oriented"},
  };
  for (const Damage& d : damages) {
    d.apply();
    ::testing::internal::CaptureStderr();
    bool reused = true;
    const TetMesh m = read_level_mesh(path, LengthUnit::Metre, nullptr, &reused);
    const std::string said = ::testing::internal::GetCapturedStderr();
    EXPECT_FALSE(reused) << d.what;
    EXPECT_NE(said.find("ignored the mesh cache"), std::string::npos) << d.what << ": " << said;
    EXPECT_NE(said.find(d.said), std::string::npos) << d.what << ": " << said;
    expect_same(m, expected);
    read_level_mesh(path, LengthUnit::Metre, &quiet, &reused);
    EXPECT_TRUE(reused) << "rewritten after " << d.what;
  }
}

TEST(MeshCache, OtherFormatsAndUnreadableFilesAreNotKept) {
  CacheFolder folder("meshes");
  ScratchDir dir;
  write_file(dir / "m.mesh", mrsim::test::medit_text({{"0", "0", "0"}, {"1", "0", "0"},
                                                      {"0", "1", "0"}, {"0", "0", "1"}},
                                                     {{1, 2, 3, 4}}));
  bool reused = true;
  EXPECT_EQ(read_level_mesh(dir / "m.mesh", LengthUnit::Metre, nullptr, &reused).tets.size(), 1u);
  EXPECT_FALSE(reused);
  // read_tet_mesh's own messages, and nothing kept.
  const auto message = [](const std::function<void()>& read) {
    return mrsim::test::input_error_of(read);
  };
  EXPECT_EQ(message([&] { read_level_mesh(dir / "absent.vtu", LengthUnit::Metre); }),
            message([&] { read_tet_mesh(dir / "absent.vtu", LengthUnit::Metre); }));
  write_file(dir / "empty.vtu", "");
  EXPECT_EQ(message([&] { read_level_mesh(dir / "empty.vtu", LengthUnit::Metre); }),
            message([&] { read_tet_mesh(dir / "empty.vtu", LengthUnit::Metre); }));
  std::string torn = warned_vtu();
  torn.resize(torn.size() / 2);
  write_file(dir / "torn.vtu", torn);
  EXPECT_EQ(message([&] { read_level_mesh(dir / "torn.vtu", LengthUnit::Metre); }),
            message([&] { read_tet_mesh(dir / "torn.vtu", LengthUnit::Metre); }));
  EXPECT_TRUE(folder.files("meshes").empty());
}
