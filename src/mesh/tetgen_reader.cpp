#include "mesh/tetgen_reader.hpp"

#include <cctype>
#include <climits>
#include <string>

#include "mesh/input_cursor.hpp"
#include "mesh/mesh_input.hpp"

namespace mrsim {
namespace {

constexpr std::int64_t kMaxAttributes = 1000;

// The file with the other extension, in the case of the given one (m.NODE -> m.ELE).
std::filesystem::path sibling(const std::filesystem::path& given, std::string extension) {
  const std::string given_ext = given.extension().string();
  if (!given_ext.empty() && std::isupper(static_cast<unsigned char>(given_ext.back())))
    for (char& c : extension) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  std::filesystem::path p = given;
  p.replace_extension(extension);
  std::error_code ec;
  if (!std::filesystem::exists(p, ec))
    throw mesh_error(given, cat("a TetGen mesh needs both .node and .ele files, and ", p.string(), " was not found"));
  return p;
}

struct TetgenNodes {
  std::vector<Vec3> points;
  std::int64_t base = 0;  // index of the first node: 0 or 1
};

// "<#points> <dimension 3> <#attributes> <boundary marker 0|1>", then one line per node:
// "<index> <x> <y> <z> [attributes] [marker]".
TetgenNodes read_nodes(const std::filesystem::path& path) {
  const std::string bytes = read_whole_file(path);
  InputCursor in(bytes, path, '#');
  const std::int64_t n = in.integer_in("the number of nodes", 0, INT_MAX);
  if (n == 0) in.fail("the .node file holds no nodes (they may be in a .poly file, which mrsim does not read)");
  const std::int64_t dim = in.integer("the dimension");
  if (dim != 3) in.fail(cat("dimension is ", dim, "; mrsim needs a 3-D mesh"));
  const std::int64_t attributes = in.integer_in("the number of node attributes", 0, kMaxAttributes);
  const std::int64_t markers = in.integer_in("the boundary marker flag", 0, 1);
  in.end_line("the .node header");
  in.require_room(static_cast<std::uint64_t>(n), 2 * static_cast<std::size_t>(4 + attributes + markers), "nodes");

  TetgenNodes nodes;
  nodes.points.resize(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) {
    const std::int64_t index = in.integer("a node index");
    if (i == 0 && index != 0 && index != 1) in.fail(cat("first node index is ", index, "; TetGen numbers nodes from 0 or 1"));
    if (i == 0) nodes.base = index;
    if (index != nodes.base + i)
      in.fail(cat("node index ", index, ", expected ", nodes.base + i, " (TetGen numbers nodes consecutively)"));
    Vec3& p = nodes.points[static_cast<std::size_t>(i)];
    for (int a = 0; a < 3; ++a) p[a] = in.real("a node coordinate");
    for (std::int64_t a = 0; a < attributes; ++a) in.real("a node attribute");
    if (markers) in.integer("a boundary marker");
    in.end_line(cat("node ", index, " (the header announces ", attributes, " attributes and ", markers, " marker)"));
  }
  return nodes;
}

// "<#tetrahedra> <nodes per tetrahedron 4|10> <#region attributes>", then
// "<index> <n1> <n2> <n3> <n4> [attributes]".
void read_tets(const std::filesystem::path& path, const TetgenNodes& nodes, RawMesh& raw) {
  const std::string bytes = read_whole_file(path);
  InputCursor in(bytes, path, '#');
  const std::int64_t m = in.integer_in("the number of tetrahedra", 0, INT_MAX);
  const std::int64_t per_tet = in.integer("the number of nodes per tetrahedron");
  if (per_tet == 10) in.fail("second-order tetrahedra (10 nodes) are not supported; export linear elements (tetgen without -o2)");
  if (per_tet != 4) in.fail(cat(per_tet, " nodes per tetrahedron; TetGen writes 4 (or 10)"));
  const std::int64_t attributes = in.integer_in("the number of region attributes", 0, kMaxAttributes);
  in.end_line("the .ele header");
  in.require_room(static_cast<std::uint64_t>(m), 2 * static_cast<std::size_t>(5 + attributes), "tetrahedra");

  const auto n = static_cast<std::int64_t>(nodes.points.size());
  raw.tets.resize(static_cast<std::size_t>(m));
  raw.tet_ids.resize(static_cast<std::size_t>(m));
  for (std::int64_t k = 0; k < m; ++k) {
    const std::int64_t id = in.integer("a tetrahedron index");
    for (int& v : raw.tets[static_cast<std::size_t>(k)]) {
      const std::int64_t node = in.integer("a node of a tetrahedron");
      if (node < nodes.base || node >= nodes.base + n)
        in.fail(cat("tetrahedron ", id, " refers to node ", node, ", but the .node file holds nodes ", nodes.base,
                    " to ", nodes.base + n - 1));
      v = static_cast<int>(node - nodes.base);
    }
    for (std::int64_t a = 0; a < attributes; ++a) in.real("a region attribute");
    in.end_line(cat("tetrahedron ", id));
    raw.tet_ids[static_cast<std::size_t>(k)] = id;
  }
}

}  // namespace

RawMesh read_tetgen(const std::filesystem::path& path) {
  const std::filesystem::path node_path = sibling(path, ".node");
  const std::filesystem::path ele_path = sibling(path, ".ele");
  TetgenNodes nodes = read_nodes(node_path);
  RawMesh raw;
  read_tets(ele_path, nodes, raw);
  raw.format = "tetgen";
  raw.point_noun = "node";
  raw.point_ids.resize(nodes.points.size());
  for (std::size_t i = 0; i < nodes.points.size(); ++i) raw.point_ids[i] = nodes.base + static_cast<std::int64_t>(i);
  raw.points = std::move(nodes.points);
  return raw;
}

}  // namespace mrsim
