#pragma once
// Hands a triangulated surface to gmsh as the mesh of one discrete surface entity (nodes
// numbered 1..n in the surface's point order), which gmsh either reclassifies and remeshes
// (SurfaceSource) or keeps as the boundary of the volume (SimplifiedSurfaceSource).
#include "meshing/surface_mesh.hpp"

namespace mrsim {

/// Adds the surface to the current gmsh model; returns the surface entity's tag.
int add_discrete_surface(const SurfaceMesh& surface);

}  // namespace mrsim
