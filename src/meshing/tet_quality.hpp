#pragma once
// Quality statistics of a tetrahedral mesh, as reported per level in PREFIX_quality.json and
// used to rank the candidates of the size search.
#include <array>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

inline constexpr int kRadiusRatioBins = 10;

struct TetQuality {
  std::size_t points = 0;
  std::size_t tets = 0;
  std::size_t boundary_triangles = 0;
  double min_dihedral_deg = 0.0;
  double max_dihedral_deg = 0.0;
  // Radius ratio 3 r_in / R_circ: 1 for the regular tet, 0 for a flat one.
  double min_radius_ratio = 0.0;
  double mean_radius_ratio = 0.0;
  std::array<std::size_t, kRadiusRatioBins> radius_ratio_histogram{};  // bins of width 0.1
  double volume = 0.0;  // m^3
  double min_edge = 0.0, mean_edge = 0.0, max_edge = 0.0;  // over distinct edges, m
};

TetQuality measure_quality(const TetMesh& mesh);

/// Ranking of candidates: larger minimum dihedral angle first, then larger mean radius ratio.
bool better_quality(const TetQuality& a, const TetQuality& b);

}  // namespace mrsim
