#pragma once
// The thesis' "try several, keep the best" loop (method.md §4.1 point 3), on the mesh size:
// a secant search on log(size) drives the tet count to the target
// (count ~ size^-3), every mesh it makes is a candidate, four more are made just around the
// best size; then, among the candidates within the tolerance band of the target, the one
// with the best quality wins (minimum dihedral angle, then mean radius ratio). When no
// candidate falls in the band (tiny targets, where the count jumps with the size and is not
// monotone in it), a grid of sizes from 0.8 to 1.4 times the best is tried until one does;
// failing that, the closest count wins.
#include <cstddef>
#include <string>

#include "mesh/tet_mesh.hpp"
#include "meshing/geometry_source.hpp"
#include "meshing/tet_quality.hpp"
#include "meshing/volume_mesher.hpp"

namespace mrsim {

struct SearchOptions {
  double tolerance = 0.2;       // accepted relative deviation of the tet count
  double close_enough = 0.05;   // the secant search stops within this deviation
  int max_steps = 6;            // secant steps per algorithm
  bool match_volume = true;     // restore the input's volume (volume_match.hpp)
};

struct LevelMesh {
  TetMesh mesh;
  TetQuality quality;
  MeshSettings settings;
  double raw_volume = 0.0;        // m^3, as gmsh made it, before volume matching
  double boundary_offset = 0.0;   // m, normal offset applied by volume matching
  int candidates = 0;        // meshes made
  int failed_attempts = 0;   // gmsh errors (skipped)
  bool within_tolerance = false;
  bool simplified_surface = false;  // made by the source's fallback (GeometrySource::fallback)
};

/// When gmsh fails at every size tried and the source has a fallback, the same search runs on
/// the fallback. Throws InputError when that fails too (the message carries gmsh's reasons).
LevelMesh search_level(const GeometrySource& source, std::size_t target_tets,
                       const SearchOptions& options = {});

}  // namespace mrsim
