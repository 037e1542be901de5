// Wavefront OBJ: "v x y z [w]" and "f a b c ..." where each corner is "v", "v/vt", "v//vn" or
// "v/vt/vn", 1-based or negative (relative to the vertices read so far). Normals, texture
// coordinates, groups and materials are ignored; lines and points ("l", "p") are rejected
// because they cannot bound a solid.
#include <charconv>

#include "meshing/surface_readers.hpp"
#include "meshing/text_lines.hpp"

namespace mrsim {
namespace {

int obj_corner(const TextLines& lines, std::size_t index, std::size_t vertex_count) {
  const std::string_view token = lines.tokens()[index];
  const std::string_view vertex = token.substr(0, token.find('/'));
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(vertex.data(), vertex.data() + vertex.size(), v);
  if (ec != std::errc() || end != vertex.data() + vertex.size() || v == 0) {
    lines.fail("bad face corner '" + std::string(token) + "'");
  }
  const auto count = static_cast<std::int64_t>(vertex_count);
  const std::int64_t zero_based = v > 0 ? v - 1 : count + v;
  if (zero_based < 0 || zero_based >= count) {
    lines.fail("vertex index " + std::to_string(v) + " refers to no vertex read so far (" +
               std::to_string(count) + ")");
  }
  return static_cast<int>(zero_based);
}

}  // namespace

SurfaceMesh read_obj(const std::string& bytes, const std::filesystem::path& path) {
  TextLines lines(bytes, path, '#');
  SurfaceMesh surface;
  int face_number = 0;
  while (lines.next()) {
    const std::string_view kind = lines.tokens()[0];
    if (kind == "v") {
      surface.points.emplace_back(lines.real(1), lines.real(2), lines.real(3));
    } else if (kind == "f") {
      if (lines.tokens().size() < 4) lines.fail("a face needs at least 3 vertices");
      std::vector<int> corners;
      for (std::size_t k = 1; k < lines.tokens().size(); ++k) {
        corners.push_back(obj_corner(lines, k, surface.points.size()));
      }
      add_polygon(surface, corners, ++face_number);
    } else if (kind == "l" || kind == "p") {
      lines.fail("line and point elements cannot bound a solid");
    }
  }
  return surface;
}

}  // namespace mrsim
