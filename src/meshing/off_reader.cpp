// OFF (Geomview Object File Format): "OFF", counts "V F E", V lines "x y z", F lines
// "n i1 ... in" (0-based, polygons allowed). Per-vertex normals or colours (NOFF, COFF) and
// per-face colours after the indices are ignored.
#include "meshing/surface_readers.hpp"
#include "meshing/text_lines.hpp"

namespace mrsim {
namespace {

struct OffCounts {
  std::int64_t vertices = 0;
  std::int64_t faces = 0;
};

OffCounts read_off_header(TextLines& lines) {
  if (!lines.next()) lines.fail_file("empty file");
  const std::string_view keyword = lines.tokens()[0];
  if (keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF") {
    lines.fail("not an OFF file (first keyword '" + std::string(keyword) + "')");
  }
  std::size_t first = 1;  // the counts may follow the keyword on the same line
  if (lines.tokens().size() == 1) {
    if (!lines.next()) lines.fail_file("missing vertex and face counts");
    first = 0;
  }
  OffCounts counts{lines.integer(first), lines.integer(first + 1)};
  if (counts.vertices < 3 || counts.faces < 1) {
    lines.fail("implausible counts: " + std::to_string(counts.vertices) + " vertices, " +
               std::to_string(counts.faces) + " faces");
  }
  return counts;
}

std::vector<int> read_off_face(const TextLines& lines, std::int64_t vertex_count) {
  const std::int64_t n = lines.integer(0);
  if (n < 3) lines.fail("a face needs at least 3 vertices, found " + std::to_string(n));
  if (static_cast<std::size_t>(n) + 1 > lines.tokens().size()) {
    lines.fail("face announces " + std::to_string(n) + " vertices but lists fewer");
  }
  std::vector<int> corners;
  for (std::int64_t k = 1; k <= n; ++k) {
    const std::int64_t v = lines.integer(static_cast<std::size_t>(k));
    if (v < 0 || v >= vertex_count) {
      lines.fail("vertex index " + std::to_string(v) + " out of range [0, " +
                 std::to_string(vertex_count - 1) + "]");
    }
    corners.push_back(static_cast<int>(v));
  }
  return corners;
}

}  // namespace

SurfaceMesh read_off(const std::string& bytes, const std::filesystem::path& path) {
  TextLines lines(bytes, path, '#');
  const OffCounts counts = read_off_header(lines);
  SurfaceMesh surface;
  for (std::int64_t i = 0; i < counts.vertices; ++i) {
    if (!lines.next()) lines.fail_file("ends after " + std::to_string(i) + " of " +
                                       std::to_string(counts.vertices) + " vertices");
    surface.points.emplace_back(lines.real(0), lines.real(1), lines.real(2));
  }
  for (std::int64_t f = 0; f < counts.faces; ++f) {
    if (!lines.next()) lines.fail_file("ends after " + std::to_string(f) + " of " +
                                       std::to_string(counts.faces) + " faces");
    add_polygon(surface, read_off_face(lines, counts.vertices), static_cast<int>(f + 1));
  }
  return surface;
}

}  // namespace mrsim
