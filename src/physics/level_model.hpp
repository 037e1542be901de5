#pragma once
// Everything precomputed for one mesh level (method.md §2): geometry, connectivity, masses,
// edge matrices, the Laplacian weights of §3.1, and per-point mesh sizes. Immutable during a run.
#include <vector>

#include "physics/edge_operators.hpp"
#include "physics/material_law.hpp"
#include "physics/point_adjacency.hpp"
#include "physics/spectral_bound.hpp"
#include "physics/stable_step_bound.hpp"
#include "physics/tet_geometry.hpp"

namespace mrsim {

struct LevelModel {
  const TetMesh* mesh = nullptr;
  MaterialLaw law;
  TetGeometry geo;
  PointAdjacency adj;
  std::vector<double> mass;          // kg, lumped
  std::vector<double> lumped_volume; // V*_i = Σ V_t / 4
  std::vector<double> mean_edge;     // h_i, mean rest length of the edges at i
  std::vector<double> min_edge;      // shortest rest edge at i
  std::vector<Mat3> K;               // λA + μB per CSR entry (used by the Cauchy force)
  std::vector<Mat3> D;               // φA + ψB per CSR entry (Cauchy damping); empty if undamped
  std::vector<double> laplacian_w;   // w_ij = -Σ_t V_t ∇N_i·∇N_j per CSR entry (§3.1)
  TetEnergyBounds bounds;            // energy bounds of each tet (stable step)
  // λ_max(M⁻¹K), λ_max(M⁻¹D) of the level alone and the scales they give its point bounds for
  // one global step (physics/spectral_bound.hpp, calibrated()).
  SpectralScale stiffness_spectrum, damping_spectrum;
  std::vector<PointInertia> star;    // mass and bounds of each point's whole star

  int num_points() const { return adj.num_points(); }
  int num_tets() const { return static_cast<int>(geo.tets.size()); }
};

LevelModel build_level_model(const TetMesh& mesh, const MaterialLaw& law);

/// A point bound of level `m` (its star, or what reaches it in the hierarchy, without contact)
/// scaled by the level's spectrum, for the one global step: the level alone is then estimated
/// at kSpectralMargin of its largest eigenvalue instead of 2–2.5 times it. Time levels keep the
/// proven local bounds: a uniform scale could make a point whose star bound is tight, next to
/// one where it is loose, step beyond its own limit (the tiny-tet slab of
/// tests/simulation/test_time_levels.cpp did).
PointInertia calibrated(PointInertia p, const LevelModel& m);

}  // namespace mrsim
