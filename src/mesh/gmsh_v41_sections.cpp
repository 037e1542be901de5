// MSH 4.1 $Nodes and $Elements (gmsh manual, "MSH file format"). Both are split in entity
// blocks; node tags of a block come first, then their coordinates (plus parametric
// coordinates, which mrsim skips). Binary files hold 4-byte ints for the block headers,
// 8-byte size_t for counts and tags, and 8-byte doubles.
#include <cstdint>
#include <limits>

#include "mesh/gmsh_sections.hpp"
#include "mesh/mesh_input.hpp"

namespace mrsim {
namespace {

constexpr auto kMaxTag = std::numeric_limits<std::int64_t>::max();

// A size_t field: a token in ASCII files, 8 bytes in binary ones.
std::int64_t size_field(InputCursor& in, bool binary, const char* what) {
  if (!binary) return in.integer_in(what, 0, kMaxTag);
  const auto value = in.binary<std::uint64_t>(what);
  if (value > static_cast<std::uint64_t>(kMaxTag)) in.fail(cat(what, " is too large: ", value));
  return static_cast<std::int64_t>(value);
}

// An int field (entity dimension, tag, element type, parametric flag).
int int_field(InputCursor& in, bool binary, const char* what) {
  if (!binary) return static_cast<int>(in.integer_in(what, INT_MIN, INT_MAX));
  return in.binary<std::int32_t>(what);
}

double real_field(InputCursor& in, bool binary, const char* what) {
  return binary ? in.binary<double>(what) : in.real(what);
}

struct SectionHeader {
  std::int64_t blocks = 0, count = 0;
};

// "numEntityBlocks numX minTag maxTag": the tag range is not needed (NodeTagMap finds it).
SectionHeader read_section_header(InputCursor& in, bool binary, const char* what, std::size_t min_bytes_each) {
  SectionHeader h;
  h.blocks = size_field(in, binary, "the number of entity blocks");
  h.count = size_field(in, binary, what);
  size_field(in, binary, "the smallest tag");
  size_field(in, binary, "the largest tag");
  if (h.count > kMaxGmshCount) in.fail(cat("too many ", what, ": ", h.count));
  in.require_room(static_cast<std::uint64_t>(h.count), min_bytes_each, what);
  in.require_room(static_cast<std::uint64_t>(h.blocks), binary ? 20 : 8, "entity blocks");
  return h;
}

std::int64_t read_node_block(InputCursor& in, bool binary, std::int64_t left, GmshContent& content) {
  const int dim = int_field(in, binary, "the entity dimension of a node block");
  int_field(in, binary, "the entity tag of a node block");
  const int parametric = int_field(in, binary, "the parametric flag of a node block");
  const std::int64_t n = size_field(in, binary, "the number of nodes in a block");
  if (dim < 0 || dim > 3) in.fail(cat("node block of entity dimension ", dim));
  if (parametric != 0 && parametric != 1) in.fail(cat("node block with parametric flag ", parametric));
  if (n > left) in.fail("the node blocks hold more nodes than the $Nodes header announces");
  const int values = 3 + (parametric ? dim : 0);
  in.require_room(static_cast<std::uint64_t>(n), binary ? 8 * (1 + values) : 2 * (1 + values), "nodes");
  const std::size_t first = content.node_tags.size();
  for (std::int64_t i = 0; i < n; ++i) {
    // Tags first, then coordinates: store tags with a placeholder point, fill points below.
    add_gmsh_node(in, content, size_field(in, binary, "a node tag"), Vec3::Zero());
  }
  for (std::int64_t i = 0; i < n; ++i) {
    Vec3& p = content.points[first + static_cast<std::size_t>(i)];
    for (int v = 0; v < values; ++v) {
      const double x = real_field(in, binary, "a node coordinate");
      if (v < 3) p[v] = x;
    }
  }
  return n;
}

std::int64_t read_element_block(InputCursor& in, bool binary, std::int64_t left, GmshContent& content) {
  int_field(in, binary, "the entity dimension of an element block");
  const int entity = int_field(in, binary, "the entity tag of an element block");
  const int type = int_field(in, binary, "the element type of an element block");
  const std::int64_t n = size_field(in, binary, "the number of elements in a block");
  if (n > left) in.fail("the element blocks hold more elements than the $Elements header announces");
  const GmshElementType& et = accepted_gmsh_type(in, type, cat("element block of entity ", entity));
  in.require_room(static_cast<std::uint64_t>(n), binary ? 8 * (1 + et.nodes) : 2 * (1 + et.nodes), "elements");
  std::int64_t nodes[kMaxGmshElementNodes];
  for (std::int64_t e = 0; e < n; ++e) {
    const std::int64_t tag = size_field(in, binary, "an element tag");
    for (int k = 0; k < et.nodes; ++k) nodes[k] = size_field(in, binary, "a node tag of an element");
    if (!binary) in.end_line(cat("the nodes of element ", tag));
    add_gmsh_element(content, et, tag, nodes);
  }
  return n;
}

}  // namespace

void read_gmsh41_nodes(InputCursor& in, bool binary, GmshContent& content) {
  const SectionHeader h = read_section_header(in, binary, "nodes", binary ? 8 + 3 * 8 : 8);
  content.node_tags.reserve(static_cast<std::size_t>(h.count));
  content.points.reserve(static_cast<std::size_t>(h.count));
  std::int64_t read = 0;
  for (std::int64_t b = 0; b < h.blocks; ++b) read += read_node_block(in, binary, h.count - read, content);
  if (read != h.count) in.fail(cat("$Nodes announces ", h.count, " nodes but its blocks hold ", read));
  in.expect("$EndNodes");
}

void read_gmsh41_elements(InputCursor& in, bool binary, GmshContent& content) {
  const SectionHeader h = read_section_header(in, binary, "elements", binary ? 8 * 2 : 4);
  std::int64_t read = 0;
  for (std::int64_t b = 0; b < h.blocks; ++b) read += read_element_block(in, binary, h.count - read, content);
  if (read != h.count) in.fail(cat("$Elements announces ", h.count, " elements but its blocks hold ", read));
  in.expect("$EndElements");
}

}  // namespace mrsim
