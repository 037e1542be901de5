#pragma once
// Internal to the gmsh reader: the $Nodes and $Elements parsers of MSH 2.x and 4.1 (ASCII and
// binary) and what they collect. Node tags are resolved only once the whole file is read, so
// the parsers do not depend on the order of the sections.
#include <array>
#include <climits>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "mesh/gmsh_element_types.hpp"
#include "mesh/input_cursor.hpp"

namespace mrsim {

struct GmshContent {
  std::vector<std::int64_t> node_tags;
  std::vector<Vec3> points;
  std::vector<std::int64_t> tet_tags;
  std::vector<std::array<std::int64_t, 4>> tet_nodes;  // node tags, resolved later
  std::map<std::string, std::size_t> ignored;          // "triangles" -> count
};

/// Counts must fit the int indices of TetMesh.
inline constexpr std::int64_t kMaxGmshCount = INT_MAX;
/// The largest node count of a known element type (fourth-order hexahedron).
inline constexpr int kMaxGmshElementNodes = 125;

// Shared by both versions (gmsh_content.cpp).
void add_gmsh_node(InputCursor& in, GmshContent& content, std::int64_t tag, const Vec3& p);
/// The element type, or an InputError if elements of this type cannot be loaded.
/// `which` names the element or block in the message ("element 17").
const GmshElementType& accepted_gmsh_type(InputCursor& in, int type, const std::string& which);
void add_gmsh_element(GmshContent& content, const GmshElementType& type, std::int64_t tag,
                      const std::int64_t* node_tags);

// MSH 2.x (gmsh_v2_sections.cpp); the cursor is just after "$Nodes" / "$Elements".
void read_gmsh2_nodes(InputCursor& in, bool binary, GmshContent& content);
void read_gmsh2_elements(InputCursor& in, bool binary, GmshContent& content);

// MSH 4.1 (gmsh_v41_sections.cpp).
void read_gmsh41_nodes(InputCursor& in, bool binary, GmshContent& content);
void read_gmsh41_elements(InputCursor& in, bool binary, GmshContent& content);

}  // namespace mrsim
