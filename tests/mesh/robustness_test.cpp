// Every reader against damaged copies of the fixtures: truncated at many lengths, and with
// single bytes overwritten. Each read must either throw InputError or return a valid mesh
// (indices in range, finite points, positive volumes); never crash, hang, or throw anything
// else. Run under -DMRSIM_SANITIZE=ON, this also proves no read goes out of bounds.
#include <gtest/gtest.h>

#include <random>

#include "mesh_test_support.hpp"

namespace mrsim::test {
namespace {

struct Damaged {
  const char* file;     // fixture to damage
  const char* sibling;  // TetGen partner, copied intact ("" if none)
};

const Damaged kFiles[] = {
    {"box_msh22_ascii.msh", ""},    {"box_msh22_binary.msh", ""},         {"box_msh41_ascii.msh", ""},
    {"box_msh41_binary.msh", ""},   {"box_appended_zlib.vtu", ""},        {"box_appended_zlib_bigendian.vtu", ""},
    {"box_appended_base64.vtu", ""},
    {"box_inline_zlib.vtu", ""},    {"box_ascii.vtu", ""},                {"box_medit.mesh", ""},
    {"box_tetgen_base0.node", "box_tetgen_base0.ele"}, {"box_tetgen_base1.ele", "box_tetgen_base1.node"},
};

void expect_valid(const TetMesh& m) {
  const auto n = static_cast<int>(m.points.size());
  for (const Vec3& p : m.points) ASSERT_TRUE(p.allFinite());
  for (const Tet& t : m.tets) {
    for (int v : t) ASSERT_TRUE(v >= 0 && v < n);
    ASSERT_GT(signed_volume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]), 0);
  }
}

// InputError or a valid mesh; anything else fails the test.
void read_damaged(const fs::path& path, const std::string& what) {
  try {
    const TetMesh m = read_tet_mesh(path, LengthUnit::Metre);
    expect_valid(m);
  } catch (const InputError& e) {
    ASSERT_EQ(std::string(e.what()).find(path.parent_path().string()), 0u) << what << ": " << e.what();
  } catch (const std::exception& e) {
    FAIL() << what << ": unexpected exception " << e.what();
  }
}

// Copies `d` (and its TetGen partner) into `scratch`; returns the damaged file's path.
fs::path stage(const Damaged& d, const ScratchDir& scratch) {
  if (*d.sibling) write_file(scratch / d.sibling, read_file(fixture(d.sibling)));
  return scratch / d.file;
}

// One test per kind of damage over all files (each ctest entry is a process that loads gmsh
// and VTK); SCOPED_TRACE names the file on failure.
TEST(Robustness, TruncatedCopiesFailCleanly) {
  for (const Damaged& d : kFiles) {
    SCOPED_TRACE(d.file);
    ScratchDir scratch;
    const std::string original = read_file(fixture(d.file));
    const fs::path target = stage(d, scratch);
    std::vector<std::size_t> lengths;
    for (std::size_t i = 0; i < 48; ++i) lengths.push_back(i);  // the headers, byte by byte
    for (std::size_t i = 1; i < 40; ++i) lengths.push_back(original.size() * i / 40);
    for (std::size_t len : lengths) {
      if (len >= original.size()) continue;
      write_file(target, original.substr(0, len));
      read_damaged(target, "truncated to " + std::to_string(len) + " bytes");
    }
  }
}

TEST(Robustness, CorruptedBytesFailCleanlyOrGiveAValidMesh) {
  std::mt19937 random(12345);  // fixed: the same damage every run
  const char values[] = {'\0', '\xff', '\x7f', '9', '-', ' ', '\n', 'e', '$', '<'};
  for (const Damaged& d : kFiles) {
    SCOPED_TRACE(d.file);
    ScratchDir scratch;
    const std::string original = read_file(fixture(d.file));
    const fs::path target = stage(d, scratch);
    for (int trial = 0; trial < 60; ++trial) {
      std::string bytes = original;
      const std::size_t at = random() % bytes.size();
      bytes[at] = values[random() % sizeof values];
      write_file(target, bytes);
      read_damaged(target, "byte " + std::to_string(at) + " changed");
    }
  }
}

}  // namespace
}  // namespace mrsim::test
