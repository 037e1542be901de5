// Every surface format gives the same closed cube; malformed files name the file and line.
#include <cstdint>
#include <cstring>

#include "meshing/surface_checks.hpp"
#include "meshing/surface_readers.hpp"
#include "meshing_test_support.hpp"

namespace mrsim::test {
namespace {

const double kCube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const int kFaces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                           {2, 3, 7}, {2, 7, 6}, {1, 2, 6}, {1, 6, 5}, {0, 4, 7}, {0, 7, 3}};

double checked_volume(const std::filesystem::path& file) {
  SurfaceMesh s = read_surface(file);
  const SurfaceCheckReport r = check_surface(s, file.string());
  EXPECT_EQ(s.points.size(), 8u);
  EXPECT_EQ(s.triangles.size(), 12u);
  return r.enclosed_volume;
}

std::string ascii_stl() {
  std::string text = "solid cube\n";
  for (const auto& f : kFaces) {
    text += " facet normal 0 0 0\n  outer loop\n";
    for (int v : f) {
      text += "   vertex " + std::to_string(kCube[v][0]) + " " + std::to_string(kCube[v][1]) + " " +
              std::to_string(kCube[v][2]) + "\n";
    }
    text += "  endloop\n endfacet\n";
  }
  return text + "endsolid cube\n";
}

template <class T>
void append(std::string& bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

std::string binary_stl() {
  std::string bytes(80, ' ');
  append<std::uint32_t>(bytes, 12);
  for (const auto& f : kFaces) {
    for (int k = 0; k < 3; ++k) append<float>(bytes, 0.0f);
    for (int v : f) {
      for (int k = 0; k < 3; ++k) append<float>(bytes, static_cast<float>(kCube[v][k]));
    }
    append<std::uint16_t>(bytes, 0);
  }
  return bytes;
}

std::string ply(bool binary) {
  std::string text = std::string("ply\nformat ") + (binary ? "binary_little_endian" : "ascii") +
                     " 1.0\ncomment a cube\nelement vertex 8\nproperty float x\nproperty float y\n"
                     "property float z\nproperty uchar red\nelement face 12\n"
                     "property list uchar int vertex_indices\nend_header\n";
  for (const auto& p : kCube) {
    if (binary) {
      for (double c : p) append<float>(text, static_cast<float>(c));
      append<std::uint8_t>(text, 7);
    } else {
      text += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + " 7\n";
    }
  }
  for (const auto& f : kFaces) {
    if (binary) {
      append<std::uint8_t>(text, 3);
      for (int v : f) append<std::int32_t>(text, v);
    } else {
      text += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
    }
  }
  return text;
}

TEST(SurfaceReaders, EveryFormatGivesTheUnitCube) {
  ScratchDir dir;
  EXPECT_NEAR(checked_volume(dir.write("cube.off", cube_off())), 1.0, 1e-12);
  EXPECT_NEAR(checked_volume(dir.write("cube.stl", ascii_stl())), 1.0, 1e-12);
  EXPECT_NEAR(checked_volume(dir.write("cube_binary.STL", binary_stl())), 1.0, 1e-12);
  EXPECT_NEAR(checked_volume(dir.write("cube.ply", ply(false))), 1.0, 1e-12);
  EXPECT_NEAR(checked_volume(dir.write("cube_binary.ply", ply(true))), 1.0, 1e-12);
}

TEST(SurfaceReaders, ObjWithQuadsSlashesAndNegativeIndices) {
  ScratchDir dir;
  const std::string obj =
      "# cube\no cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nvn 0 0 1\n"
      "f 1//1 4//1 3//1 2//1\nf 5/1/1 6/1/1 7/1/1 8/1/1\nf 1 2 6 5\nf 3 4 8 7\nf 2 3 7 6\nf -8 -4 -1 -5\n";
  SurfaceMesh s = read_surface(dir.write("cube.obj", obj));
  EXPECT_EQ(s.triangles.size(), 12u);
  EXPECT_EQ(s.face_of.back(), 6);
  EXPECT_NEAR(check_surface(s, "cube.obj").enclosed_volume, 1.0, 1e-12);
}

TEST(SurfaceReaders, MalformedFilesNameFileAndLine) {
  ScratchDir dir;
  const auto bad_number = dir.write("bad.off", "OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n");
  expect_input_error([&] { read_surface(bad_number); }, {"bad.off:4", "expected a number, got 'x'"});
  const auto bad_index = dir.write("index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n");
  expect_input_error([&] { read_surface(bad_index); }, {"index.off:6", "out of range"});
  const auto truncated = dir.write("short.off", "OFF\n4 4 0\n0 0 0\n");
  expect_input_error([&] { read_surface(truncated); }, {"short.off", "ends after 1 of 4 vertices"});
  const auto obj = dir.write("bad.obj", "v 0 0 0\nf 1 2 3\n");
  expect_input_error([&] { read_surface(obj); }, {"bad.obj:2", "refers to no vertex"});
  const auto stl = dir.write("bad.stl", "not an stl");
  expect_input_error([&] { read_surface(stl); }, {"bad.stl", "neither ascii STL"});
  const auto ply_file = dir.write("bad.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                                             "property float x\nproperty float y\nproperty float z\nend_header\n1234");
  expect_input_error([&] { read_surface(ply_file); }, {"bad.ply", "truncated"});
  expect_input_error([&] { read_surface(dir.file("missing.off")); }, {"missing.off", "no such file"});
  const auto unknown = dir.write("cube.xyz", "");
  expect_input_error([&] { read_surface(unknown); }, {"unknown surface format '.xyz'"});
}

}  // namespace
}  // namespace mrsim::test
