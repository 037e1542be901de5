#include "mesh/gmsh_element_types.hpp"

#include <algorithm>
#include <iterator>
#include <string_view>

#include "mesh/mesh_input.hpp"

namespace mrsim {
namespace {

// Types 1-31, 92 and 93 are the ones listed by the gmsh manual (test_gmsh_element_types
// checks them against gmsh's own getElementProperties).
constexpr GmshElementType kTypes[] = {
    {1, 2, 1, "lines"},
    {2, 3, 2, "triangles"},
    {3, 4, 2, "quadrangles"},
    {4, 4, 3, "tetrahedra"},
    {5, 8, 3, "hexahedra"},
    {6, 6, 3, "prisms"},
    {7, 5, 3, "pyramids"},
    {8, 3, 1, "second-order lines"},
    {9, 6, 2, "second-order triangles"},
    {10, 9, 2, "second-order quadrangles"},
    {11, 10, 3, "second-order tetrahedra"},
    {12, 27, 3, "second-order hexahedra"},
    {13, 18, 3, "second-order prisms"},
    {14, 14, 3, "second-order pyramids"},
    {15, 1, 0, "points"},
    {16, 8, 2, "second-order quadrangles (8 nodes)"},
    {17, 20, 3, "second-order hexahedra (20 nodes)"},
    {18, 15, 3, "second-order prisms (15 nodes)"},
    {19, 13, 3, "second-order pyramids (13 nodes)"},
    {20, 9, 2, "third-order triangles (9 nodes)"},
    {21, 10, 2, "third-order triangles"},
    {22, 12, 2, "fourth-order triangles (12 nodes)"},
    {23, 15, 2, "fourth-order triangles"},
    {24, 15, 2, "fifth-order triangles (15 nodes)"},
    {25, 21, 2, "fifth-order triangles"},
    {26, 4, 1, "third-order lines"},
    {27, 5, 1, "fourth-order lines"},
    {28, 6, 1, "fifth-order lines"},
    {29, 20, 3, "third-order tetrahedra"},
    {30, 35, 3, "fourth-order tetrahedra"},
    {31, 56, 3, "fifth-order tetrahedra"},
    {92, 64, 3, "third-order hexahedra"},
    {93, 125, 3, "fourth-order hexahedra"},
};

}  // namespace

const GmshElementType* find_gmsh_element_type(int type) {
  const auto it = std::find_if(std::begin(kTypes), std::end(kTypes), [&](const auto& t) { return t.type == type; });
  return it == std::end(kTypes) ? nullptr : &*it;
}

std::string gmsh_rejection_reason(int type) {
  const GmshElementType* t = find_gmsh_element_type(type);
  if (!t)
    return cat("gmsh element type ", type, " is not supported: only linear tetrahedra (type 4) are read as cells");
  if (t->dim < 3 || type == kGmshLinearTet) return "";
  const std::string what = cat(t->plural, " (gmsh element type ", type, ") are not supported");
  if (std::string_view(t->plural).find("tetrahedra") != std::string_view::npos)
    return what + "; export linear elements (4-node tetrahedra, gmsh option Mesh.ElementOrder = 1)";
  return what + ": mrsim simulates tetrahedral meshes only; mesh the volume with tetrahedra";
}

}  // namespace mrsim
