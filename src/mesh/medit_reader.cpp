#include "mesh/medit_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <string>

#include "mesh/input_cursor.hpp"
#include "mesh/mesh_input.hpp"

namespace mrsim {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

// Keywords start with a letter; "nan" and "inf" also do, but are numbers.
bool is_keyword(std::string_view tok) {
  if (tok.empty() || !std::isalpha(static_cast<unsigned char>(tok[0]))) return false;
  double x = 0;
  const auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), x);
  return !(ec == std::errc() && end == tok.data() + tok.size());
}

// Binary .meshb files start with the int 1 (in the writer's byte order), text files with a
// keyword or a comment.
bool looks_binary(const std::string& bytes) {
  return bytes.size() >= 4 && (bytes.compare(0, 4, std::string("\1\0\0\0", 4)) == 0 ||
                               bytes.compare(0, 4, std::string("\0\0\0\1", 4)) == 0);
}

[[noreturn]] void reject_binary(const std::filesystem::path& path) {
  throw mesh_error(path, "binary Medit files (.meshb) are not supported: convert it to ASCII .mesh "
                         "(e.g. `meshio convert FILE.meshb FILE.mesh`, or open and save it in gmsh)");
}

struct MeditReader {
  InputCursor& in;
  RawMesh raw;
  std::vector<std::array<std::int64_t, 4>> tets;  // 1-based, checked once all sections are read
  bool seen_dimension = false;

  void read_vertices() {
    if (!seen_dimension) in.fail("Vertices before Dimension");
    if (!raw.points.empty()) in.fail("a second Vertices section");
    const std::int64_t n = in.integer_in("the number of vertices", 0, INT_MAX);
    in.require_room(static_cast<std::uint64_t>(n), 8, "vertices");  // "0 0 0 0\n"
    raw.points.resize(static_cast<std::size_t>(n));
    for (Vec3& p : raw.points) {
      for (int a = 0; a < 3; ++a) p[a] = in.real("a vertex coordinate");
      in.token("a vertex reference");
    }
  }

  void read_tetrahedra() {
    if (!tets.empty()) in.fail("a second Tetrahedra section");
    const std::int64_t n = in.integer_in("the number of tetrahedra", 0, INT_MAX);
    in.require_room(static_cast<std::uint64_t>(n), 10, "tetrahedra");  // "1 2 3 4 0\n"
    tets.resize(static_cast<std::size_t>(n));
    for (auto& t : tets) {
      for (auto& v : t) v = in.integer("a vertex number of a tetrahedron");
      in.token("a tetrahedron reference");
    }
  }

  // Sections mrsim does not use are numbers up to the next keyword; only the cell counts are
  // kept, so that a surface-only file can say what it contains.
  void skip_section(const std::string& keyword) {
    if (keyword == "triangles" || keyword == "edges" || keyword == "quadrilaterals") {
      const std::int64_t n = in.integer_in(cat("the number of ", keyword), 0, INT64_MAX);
      if (n > 0) raw.ignored[keyword] += static_cast<std::size_t>(n);
    }
  }

  // Returns false at End (or end of file).
  bool read_section() {
    if (in.at_end()) return false;
    const std::string_view tok = in.token("a Medit keyword");
    if (!is_keyword(tok)) in.fail(cat("expected a Medit keyword, found ", quoted_token(tok)));
    const std::string key = lower(tok);
    if (key == "end") return false;
    if (key == "meshversionformatted") in.fail("a second MeshVersionFormatted");
    if (key == "dimension") {
      const std::int64_t d = in.integer("the dimension");
      if (d != 3) in.fail(cat("this is a ", d, "-D mesh; mrsim needs a 3-D tetrahedral mesh"));
      seen_dimension = true;
    } else if (key == "vertices") {
      read_vertices();
    } else if (key == "tetrahedra") {
      read_tetrahedra();
    } else if (key.starts_with("hexahedra") || key.starts_with("prisms") || key.starts_with("pyramids") ||
               key.starts_with("polyhedra")) {
      in.fail(cat(tok, " are not supported: mrsim simulates tetrahedral meshes only"));
    } else if (key.starts_with("tetrahedra")) {
      in.fail(cat(tok, ": higher-order tetrahedra are not supported; export linear (4-vertex) tetrahedra"));
    } else {
      skip_section(key);
    }
    skip_to_keyword();
    return true;
  }

  // Whatever numbers remain before the next keyword (extra values, skipped sections).
  void skip_to_keyword() {
    while (!in.at_end() && !is_keyword(in.peek_token())) in.token("a value");
  }
};

void resolve_tets(MeditReader& r, const std::filesystem::path& path) {
  const auto n = static_cast<std::int64_t>(r.raw.points.size());
  r.raw.tets.resize(r.tets.size());
  for (std::size_t k = 0; k < r.tets.size(); ++k)
    for (int v = 0; v < 4; ++v) {
      const std::int64_t id = r.tets[k][v];
      if (id < 1 || id > n)
        throw mesh_error(path, cat("tetrahedron ", k + 1, " refers to vertex ", id, ", but Vertices holds ", n,
                                   " vertices (numbered from 1)"));
      r.raw.tets[k][v] = static_cast<int>(id - 1);
    }
}

}  // namespace

RawMesh read_medit(const std::filesystem::path& path) {
  const std::string bytes = read_whole_file(path);
  if (looks_binary(bytes)) reject_binary(path);
  InputCursor in(bytes, path, '#');
  const std::string_view first = in.token("MeshVersionFormatted");
  if (lower(first) != "meshversionformatted")
    throw mesh_error(path, "not a Medit mesh file: it does not start with MeshVersionFormatted");
  in.integer_in("the MeshVersionFormatted value", 1, 4);

  MeditReader r{in, {}, {}, false};
  while (r.read_section()) {
  }
  resolve_tets(r, path);
  r.raw.format = "medit";
  r.raw.point_ids.resize(r.raw.points.size());
  for (std::size_t i = 0; i < r.raw.points.size(); ++i) r.raw.point_ids[i] = static_cast<std::int64_t>(i) + 1;
  r.raw.tet_ids.resize(r.raw.tets.size());
  for (std::size_t k = 0; k < r.raw.tets.size(); ++k) r.raw.tet_ids[k] = static_cast<std::int64_t>(k) + 1;
  return std::move(r.raw);
}

}  // namespace mrsim
