#pragma once
// Per-tet precomputation of method.md §2.1: rest volume and the constant gradients of the four
// linear shape functions. Structure of arrays, indexed by tet.
#include <array>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace mrsim {

using TetGradients = std::array<Vec3, 4>;  // ∇N_a, a = 0..3

struct TetGeometry {
  std::vector<Tet> tets;
  std::vector<double> volume;        // V_t > 0
  // V_t times the tet's calibration factor (MaterialLaw::tet_scales; V_t itself without one):
  // what the stiffness and the damping integrate over. `volume` stays the masses' and the
  // geometry's (lumped volumes, the Laplacian criterion, patch-test weights).
  std::vector<double> elastic_volume;
  std::vector<TetGradients> grad;    // Σ_a ∇N_a = 0
};

/// Throws std::invalid_argument on a non-positive volume: meshes are checked on load.
/// `tet_scales`: one positive factor per tet for elastic_volume (null: none).
TetGeometry build_tet_geometry(const TetMesh& mesh, const std::vector<double>* tet_scales = nullptr);

/// Displacement (or velocity) gradient G = Σ_b u_b ∇N_bᵀ of one tet.
inline Mat3 tet_gradient(const TetGradients& g, const Tet& t, const Vec3* u) {
  Mat3 G = u[t[0]] * g[0].transpose();
  G.noalias() += u[t[1]] * g[1].transpose();
  G.noalias() += u[t[2]] * g[2].transpose();
  G.noalias() += u[t[3]] * g[3].transpose();
  return G;
}

}  // namespace mrsim
