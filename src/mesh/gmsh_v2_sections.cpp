// MSH 2.x $Nodes and $Elements (gmsh manual, "MSH file format version 2"). Binary files hold
// 4-byte ints and 8-byte doubles; elements come in blocks of one type behind a 3-int header.
#include <cstdint>

#include "mesh/gmsh_sections.hpp"
#include "mesh/mesh_input.hpp"

namespace mrsim {
namespace {

// Generous: gmsh writes 2 (physical, elementary), partitioned meshes a few more.
constexpr std::int64_t kMaxElementTags = 1000;

void read_ascii_elements(InputCursor& in, std::int64_t count, GmshContent& content) {
  in.require_room(static_cast<std::uint64_t>(count), 8, "elements");  // "1 15 0 1\n" at least
  std::int64_t nodes[kMaxGmshElementNodes];
  for (std::int64_t i = 0; i < count; ++i) {
    const std::int64_t tag = in.integer("an element number");
    const auto type = static_cast<int>(in.integer_in("an element type", 0, INT_MAX));
    const std::int64_t tags = in.integer_in("the number of element tags", 0, kMaxElementTags);
    for (std::int64_t t = 0; t < tags; ++t) in.integer("an element tag");
    const GmshElementType& et = accepted_gmsh_type(in, type, cat("element ", tag));
    for (int n = 0; n < et.nodes; ++n) nodes[n] = in.integer("a node tag of an element");
    in.end_line(cat("the nodes of element ", tag));
    add_gmsh_element(content, et, tag, nodes);
  }
}

void read_binary_elements(InputCursor& in, std::int64_t count, GmshContent& content) {
  std::int64_t nodes[kMaxGmshElementNodes];
  std::int64_t done = 0;
  while (done < count) {
    const int type = in.binary<std::int32_t>("an element block header");
    const std::int64_t in_block = in.binary<std::int32_t>("an element block header");
    const std::int64_t tags = in.binary<std::int32_t>("an element block header");
    if (in_block < 1 || in_block > count - done)
      in.fail(cat("element block of ", in_block, " elements, but ", count - done, " elements remain"));
    if (tags < 0 || tags > kMaxElementTags) in.fail(cat("element block with ", tags, " tags per element"));
    const GmshElementType& et = accepted_gmsh_type(in, type, "element block");
    in.require_room(static_cast<std::uint64_t>(in_block), 4 * (1 + tags + et.nodes), "elements");
    for (std::int64_t e = 0; e < in_block; ++e) {
      const std::int64_t tag = in.binary<std::int32_t>("an element number");
      for (std::int64_t t = 0; t < tags; ++t) in.binary<std::int32_t>("an element tag");
      for (int n = 0; n < et.nodes; ++n) nodes[n] = in.binary<std::int32_t>("a node tag of an element");
      add_gmsh_element(content, et, tag, nodes);
    }
    done += in_block;
  }
}

}  // namespace

void read_gmsh2_nodes(InputCursor& in, bool binary, GmshContent& content) {
  const std::int64_t count = in.integer_in("the number of nodes", 0, kMaxGmshCount);
  if (binary) in.end_line("the number of nodes");
  // Bound the count by the bytes left before reserving: "1 0 0 0\n" or int + 3 doubles.
  in.require_room(static_cast<std::uint64_t>(count), binary ? 4 + 3 * 8 : 8, "nodes");
  content.node_tags.reserve(static_cast<std::size_t>(count));
  content.points.reserve(static_cast<std::size_t>(count));
  for (std::int64_t i = 0; i < count; ++i) {
    std::int64_t tag = 0;
    Vec3 p;
    if (binary) {
      tag = in.binary<std::int32_t>("a node number");
      for (int a = 0; a < 3; ++a) p[a] = in.binary<double>("node coordinates");
    } else {
      tag = in.integer("a node number");
      for (int a = 0; a < 3; ++a) p[a] = in.real("a node coordinate");
      in.end_line(cat("node ", tag));
    }
    add_gmsh_node(in, content, tag, p);
  }
  in.expect("$EndNodes");
}

void read_gmsh2_elements(InputCursor& in, bool binary, GmshContent& content) {
  const std::int64_t count = in.integer_in("the number of elements", 0, kMaxGmshCount);
  if (binary) {
    in.end_line("the number of elements");
    read_binary_elements(in, count, content);
  } else {
    read_ascii_elements(in, count, content);
  }
  in.expect("$EndElements");
}

}  // namespace mrsim
