// STL, ascii ("solid ... facet normal ... outer loop, vertex x y z (x3) ... endsolid") and
// binary (80-byte header, uint32 count, 50 bytes per facet, little endian). A file is binary
// when its size is exactly 84 + 50 * count: some binary files also start with "solid".
// STL repeats the corners of every facet; the surface checks weld identical points.
#include <cstdint>
#include <cstring>

#include "core/error.hpp"
#include "meshing/surface_readers.hpp"
#include "meshing/text_lines.hpp"

namespace mrsim {
namespace {

float little_endian_float(const char* bytes) {
  // x86 and ARM Linux are little endian, like binary STL.
  float value = 0.0f;
  std::memcpy(&value, bytes, sizeof value);
  return value;
}

bool is_binary_stl(const std::string& bytes) {
  if (bytes.size() < 84) return false;
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, sizeof count);
  return bytes.size() == 84 + 50 * static_cast<std::uint64_t>(count);
}

SurfaceMesh read_binary_stl(const std::string& bytes) {
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, sizeof count);
  SurfaceMesh surface;
  surface.face_noun = "facet";
  for (std::uint32_t f = 0; f < count; ++f) {
    const char* facet = bytes.data() + 84 + 50 * static_cast<std::size_t>(f);
    const int first = static_cast<int>(surface.points.size());
    for (int corner = 0; corner < 3; ++corner) {
      const char* xyz = facet + 12 + 12 * corner;  // after the 12-byte normal
      surface.points.emplace_back(little_endian_float(xyz), little_endian_float(xyz + 4),
                                  little_endian_float(xyz + 8));
    }
    surface.triangles.push_back({first, first + 1, first + 2});
    surface.face_of.push_back(static_cast<int>(f + 1));
  }
  return surface;
}

SurfaceMesh read_ascii_stl(const std::string& bytes, const std::filesystem::path& path) {
  TextLines lines(bytes, path, '\0');
  SurfaceMesh surface;
  surface.face_noun = "facet";
  int facet = 0;
  std::vector<int> corners;
  while (lines.next()) {
    const std::string_view kind = lines.tokens()[0];
    if (kind == "facet") {
      ++facet;
      corners.clear();
    } else if (kind == "vertex") {
      if (facet == 0) lines.fail("'vertex' outside a facet");
      corners.push_back(static_cast<int>(surface.points.size()));
      surface.points.emplace_back(lines.real(1), lines.real(2), lines.real(3));
    } else if (kind == "endfacet") {
      if (corners.size() != 3) {
        lines.fail("facet " + std::to_string(facet) + " has " + std::to_string(corners.size()) +
                   " vertices, STL facets have 3");
      }
      add_polygon(surface, corners, facet);
    }
  }
  if (facet == 0) lines.fail_file("no facet found (neither ascii nor binary STL)");
  return surface;
}

}  // namespace

SurfaceMesh read_stl(const std::string& bytes, const std::filesystem::path& path) {
  if (is_binary_stl(bytes)) return read_binary_stl(bytes);
  if (bytes.compare(0, 5, "solid") != 0) {
    throw InputError(path.string() + ": neither ascii STL (no 'solid' keyword) nor binary STL "
                     "(size does not match the facet count)");
  }
  return read_ascii_stl(bytes, path);
}

}  // namespace mrsim
