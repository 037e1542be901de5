#pragma once
// Everything precomputed for one mesh level (method.md §2): geometry, connectivity, masses,
// edge matrices, the Laplacian weights of §3.1, and per-point mesh sizes. Immutable during a run.
#include <cstdint>
#include <limits>
#include <vector>

#include "physics/edge_operators.hpp"
#include "physics/material_law.hpp"
#include "physics/point_adjacency.hpp"
#include "physics/spectral_bound.hpp"
#include "physics/stable_step_bound.hpp"
#include "physics/tet_geometry.hpp"

namespace mrsim {

/// What the level's Lanczos runs measure at set-up (measured_spectra() in level_model.cpp), the
/// inputs of its spectral scales: λ_max(M⁻¹K), λ_max(M⁻¹D), the filtered λ_max (semi-implicit
/// only, else 0) and combined_step_limit() (infinite when undamped). A run that knows them
/// (simulation/spectrum_cache.hpp) skips the runs and gets the same model, bit for bit.
struct LevelSpectra {
  double stiffness = 0, damping = 0, filtered = 0;
  double combined = std::numeric_limits<double>::infinity();
};

struct LevelModel {
  const TetMesh* mesh = nullptr;
  MaterialLaw law;
  TetGeometry geo;
  PointAdjacency adj;
  std::vector<double> mass;           // kg, lumped
  // 1 for the points the scenario holds (`fixed`), empty when none is: they never move, so
  // neither the spectra nor the stable step look at them.
  std::vector<std::uint8_t> held;
  std::vector<double> lumped_volume;  // V*_i = Σ V_t / 4
  std::vector<double> mean_edge;      // h_i, mean rest length of the edges at i
  std::vector<double> min_edge;       // shortest rest edge at i
  // λA + μB and φA + ψB per CSR entry (D empty if undamped): the Cauchy force, the
  // semi-implicit filter and the spectra use them. Both empty when none of those needs them
  // (Green–Lagrange, explicit, spectra given: edge_matrices_needed()).
  std::vector<Mat3> K;
  std::vector<Mat3> D;
  std::vector<double> laplacian_w;    // w_ij = -Σ_t V_t ∇N_i·∇N_j per CSR entry (§3.1)
  TetEnergyBounds bounds;             // energy bounds of each tet (stable step)
  // λ_max(M⁻¹K), λ_max(M⁻¹D) of the level alone and the scales they give its point bounds for
  // one global step (physics/spectral_bound.hpp, calibrated()).
  SpectralScale stiffness_spectrum, damping_spectrum;
  // λ_max(M⁻¹(K − 2 blockdiag K)) and the semi-implicit scale (filter_scale()); measured only
  // for the semi-implicit integrators, else the thesis' rule (scale 1).
  SpectralScale filter_spectrum;
  // What calibrated() scales the damping bounds by: damping_spectrum.scale, or less where the
  // level's combined limit (stiffness and damping together, physics/spectral_bound.hpp
  // combined_step_limit()) is longer than the two maxima apart say.
  double step_damping_scale = 1;
  // The same for time levels, whose stiffness bounds stay the proven ones (damping_calibrated()).
  double time_level_damping_scale = 1;
  std::vector<PointInertia> star;  // mass and bounds of each point's whole star
  // combined_step_limit() of the level (infinite when undamped): the one measurement of
  // level_spectra() its scales do not hold.
  double combined_limit = std::numeric_limits<double>::infinity();
  // Semi-implicit time levels: each point's share of its proven stiffness bound
  // (physics/patch_spectrum.hpp, prepare_semi_implicit_time_levels()); empty otherwise.
  std::vector<double> time_level_share;

  int num_points() const { return adj.num_points(); }
  int num_tets() const { return static_cast<int>(geo.tets.size()); }
};

/// `semi_implicit`: also measure the filtered spectrum (one more Lanczos run). `held`: the
/// level's held points (select_fixed_points()), or empty; the spectra are those of the free
/// points, which the step has to keep stable. `known`: the spectra of this mesh, law, held mask
/// and integrator family measured before (level_spectra() of an earlier build): no Lanczos
/// run, and no edge matrices where nothing else needs them.
/// What a level's model computes from its mesh and law alone at most cost after the spectra:
/// the adjacency, the Laplacian weights and the tets' energy bounds (liver_probe's four levels:
/// ~26 M of a warm set-up's ~120 M instructions). A run keeps them for the next
/// (simulation/level_array_cache.hpp), as build_level_model() computes them, bit for bit.
struct LevelArrays {
  PointAdjacency adj;
  std::vector<double> laplacian_w;
  TetEnergyBounds bounds;
};

/// `known`: the spectra, not measured. `arrays`: taken (moved from), not computed; they must be
/// what this build computes for `mesh` and `law`.
LevelModel build_level_model(const TetMesh& mesh, const MaterialLaw& law,
                             bool semi_implicit = false,
                             const std::vector<std::uint8_t>& held = {},
                             const LevelSpectra* known = nullptr, LevelArrays* arrays = nullptr);

/// What the level's Lanczos runs measured (or were given), as build_level_model() takes it.
LevelSpectra level_spectra(const LevelModel& m);

/// Does a level of this law need K and D beyond its spectra? The Cauchy force gathers them and
/// the semi-implicit filter takes K's diagonal blocks; the Green–Lagrange force does not.
bool edge_matrices_needed(const MaterialLaw& law, bool semi_implicit);

/// Is point i of the level held?
inline bool is_held(const LevelModel& m, int i) { return !m.held.empty() && m.held[i]; }

/// A point bound of level `m` (its star, or what reaches it in the hierarchy, without contact)
/// scaled by the level's spectrum, for the one global step: the level alone is then estimated
/// at kSpectralMargin of its largest eigenvalue instead of 2–2.5 times it. Time levels keep the
/// proven local bounds: a uniform scale could make a point whose star bound is tight, next to
/// one where it is loose, step beyond its own limit (the tiny-tet slab of
/// tests/simulation/test_time_levels.cpp did).
/// `semi_implicit`: the stiffness takes the filtered scale instead (it stands for the stiffness
/// the filter leaves explicit; it may be negative). `time_levels`: the proven stiffness bound
/// is kept and only the damping is scaled to the level's combined limit
/// (time_level_damping_scale): where damping sets the step, the damping and stiffness modes
/// apart were 1.6–4.6 times too cautious on the liver.
/// `growth`: the point's tangent growth g now, the largest among its tets (physics/
/// tangent_growth.hpp; 0, what the set-up assumes, gives filter_spectrum itself).
/// Semi-implicit, the filtered scale follows it (filter_spectrum_at()) for one global step,
/// and the proven stiffness bound grows by time_level_stiffening(g) with time levels.
/// `damping_growth`: the point's own g_d, the largest among its tets (tangent_growths_of());
/// the damping bound grows by 1 + g_d. Explicit, both grow by what the spectral margin does
/// not cover (explicit_stiffening(), explicit_damping_growth(); 1 below g = 0.5, g_d = 0.22).
/// `point`: the point's index on the level, whose share semi-implicit time levels count
/// (time_level_share(); -1: the thesis' quarter, for a bound that is no single point's).
PointInertia calibrated(PointInertia p, const LevelModel& m, bool semi_implicit = false,
                        bool time_levels = false, double growth = 0.0,
                        double damping_growth = 0.0, int point = -1);

/// A semi-implicit level stepped on time levels: each point's share of its proven stiffness
/// bound (physics/patch_spectrum.hpp: its patches' filtered spectrum, at least the level's),
/// and the time levels' damping scale against it. A dense eigenproblem per point (about
/// 20–70 µs), so only where time levels run; a second call does nothing.
void prepare_semi_implicit_time_levels(LevelModel& m);

/// The share of point `point`'s proven stiffness bound counted with semi-implicit time levels;
/// the thesis' kSemiImplicitShare for point -1 (a bound that is no point's). Throws if the
/// level was not prepared.
double time_level_share(const LevelModel& m, int point);

/// Does the level's tangent stiffness grow with strain (Green–Lagrange)?
bool stiffens(const LevelModel& m);

/// The semi-implicit scale at tangent growth g (physics/tangent_growth.hpp): its stiffening
/// share follows filter_stiffening(g); filter_spectrum is the one at g = 0, what the set-up
/// estimate assumes. A linear law's does not change.
SpectralScale filter_spectrum_at(const LevelModel& m, double growth);

}  // namespace mrsim
