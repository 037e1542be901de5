#pragma once
// Topological checks of a triangulated surface, in the order they are run: every edge shared
// by exactly two triangles (closed, edge-manifold), one fan of triangles around every vertex
// (no pinched vertex), consistent orientation (repaired when possible), connected components
// and genus. Each failure throws InputError naming `name` and where the defect is.
#include <string>

#include "meshing/surface_mesh.hpp"

namespace mrsim {

/// Open surface (edges with one triangle) or non-manifold edges (three or more triangles).
void check_edges_closed(const SurfaceMesh& surface, const std::string& name);

/// Pinched vertices: the triangles around a vertex form two or more separate fans.
void check_vertex_fans(const SurfaceMesh& surface, const std::string& name);

/// Flips triangles so that neighbours agree on orientation; returns how many were flipped.
/// Throws for a non-orientable surface. Requires check_edges_closed to have passed.
int orient_consistently(SurfaceMesh& surface, const std::string& name);

/// Connected components (by shared edges); `component_of` receives each triangle's component.
int connected_components(const SurfaceMesh& surface, std::vector<int>* component_of = nullptr);

/// Genus of a closed, connected, orientable surface: (2 - V + E - F) / 2.
int surface_genus(const SurfaceMesh& surface);

/// "(x, y, z)": how messages name a vertex, whatever the file's numbering convention.
std::string describe_point(const Vec3& p);

}  // namespace mrsim
