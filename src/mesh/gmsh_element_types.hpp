#pragma once
// The gmsh element types mrsim knows (MSH format manual, "elm-type"): node count, dimension and
// a name for messages. Only linear tetrahedra (type 4) become cells; lower-dimensional
// elements are skipped; other 3-D cells are rejected with their name.
#include <string>

namespace mrsim {

struct GmshElementType {
  int type;
  int nodes;
  int dim;
  const char* plural;  // "second-order tetrahedra"
};

inline constexpr int kGmshLinearTet = 4;

/// nullptr for a type mrsim does not know.
const GmshElementType* find_gmsh_element_type(int type);

/// Why elements of `type` cannot be loaded, or "" if they can (linear tets) or are skipped
/// (points, lines, surfaces).
std::string gmsh_rejection_reason(int type);

}  // namespace mrsim
