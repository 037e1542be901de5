#pragma once
// Helpers for the mesh tests: where fixtures live, a scratch directory per test, small file
// writers for hand-made bad inputs, and an assertion on InputError messages.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "support/scratch_and_shared.hpp"
#include "mesh/mesh_reader.hpp"

namespace mrsim::test {

namespace fs = std::filesystem;

inline fs::path fixture_dir() { return fs::path(MRSIM_SOURCE_DIR) / "tests" / "data" / "mesh"; }
inline fs::path fixture(const std::string& name) { return fixture_dir() / name; }



inline void write_file(const fs::path& path, const std::string& bytes) {
  // Unlink first: ext4 flushes a file truncated by a rewrite when it is closed (auto_da_alloc),
  // which makes rewriting the same scratch file hundreds of times slow.
  std::error_code ec;
  fs::remove(path, ec);
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Runs `read` and returns the InputError message (empty, with a test failure, if none).
inline std::string input_error_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected InputError, but reading succeeded";
  return "";
}

/// Reading `path` must fail with an InputError that starts with the path of the faulty file
/// (`path` itself unless given: a TetGen error names the .node or .ele file at fault) and
/// contains every one of `parts`.
inline void expect_mesh_error(const fs::path& path, const std::vector<std::string>& parts,
                              const fs::path& faulty_file = {}) {
  const std::string message = input_error_of([&] { read_tet_mesh(path, LengthUnit::Metre); });
  const fs::path prefix = faulty_file.empty() ? path : faulty_file;
  EXPECT_EQ(message.rfind(prefix.string() + ": ", 0), 0u) << "message does not start with the path: " << message;
  for (const auto& p : parts) EXPECT_NE(message.find(p), std::string::npos) << "missing '" << p << "' in: " << message;
}

/// A Medit file (1-based) from raw rows: the simplest way to feed the checks bad geometry.
inline std::string medit_text(const std::vector<std::array<std::string, 3>>& points,
                              const std::vector<std::array<int, 4>>& tets) {
  std::string s = "MeshVersionFormatted 2\nDimension 3\nVertices\n" + std::to_string(points.size()) + "\n";
  for (const auto& p : points) s += p[0] + " " + p[1] + " " + p[2] + " 0\n";
  s += "Tetrahedra\n" + std::to_string(tets.size()) + "\n";
  for (const auto& t : tets)
    s += std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + " " + std::to_string(t[3]) + " 0\n";
  return s + "End\n";
}

/// Unit tet (positive with vertex order 1 2 3 4, 1-based) plus an optional extra vertex.
inline std::vector<std::array<std::string, 3>> unit_tet_points() {
  return {{"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}, {"0", "0", "1"}};
}

/// Appends the raw bytes of a value in native or swapped byte order (binary gmsh writers).
template <class T>
void put(std::string& out, T value, bool swap = false) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (swap) std::reverse(raw, raw + sizeof(T));
  out.append(raw, sizeof(T));
}

/// MSH 2.2 binary text of a mesh (node tags 1..n, one tet block), optionally byte-swapped as
/// a big-endian machine would write it.
inline std::string msh22_binary(const TetMesh& mesh, bool swap) {
  std::string s = "$MeshFormat\n2.2 1 8\n";
  put<std::int32_t>(s, 1, swap);
  s += "\n$EndMeshFormat\n$Nodes\n" + std::to_string(mesh.points.size()) + "\n";
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    put<std::int32_t>(s, static_cast<std::int32_t>(i + 1), swap);
    for (int a = 0; a < 3; ++a) put<double>(s, mesh.points[i][a], swap);
  }
  s += "\n$EndNodes\n$Elements\n" + std::to_string(mesh.tets.size()) + "\n";
  put<std::int32_t>(s, 4, swap);
  put<std::int32_t>(s, static_cast<std::int32_t>(mesh.tets.size()), swap);
  put<std::int32_t>(s, 2, swap);
  for (std::size_t k = 0; k < mesh.tets.size(); ++k) {
    put<std::int32_t>(s, static_cast<std::int32_t>(k + 1), swap);
    put<std::int32_t>(s, 1, swap);
    put<std::int32_t>(s, 1, swap);
    for (int v : mesh.tets[k]) put<std::int32_t>(s, v + 1, swap);
  }
  return s + "\n$EndElements\n";
}

inline double total_volume(const TetMesh& m) {
  double v = 0;
  for (const auto& t : m.tets) v += signed_volume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]);
  return v;
}

}  // namespace mrsim::test
