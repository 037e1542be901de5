#pragma once
// Per-tet precomputation of method.md §2.1: rest volume and the constant gradients of the four
// linear shape functions. Structure of arrays, indexed by tet.
#include <array>
#include <vector>

#include "mesh/tet_mesh.hpp"
#include "physics/material_law.hpp"

namespace mrsim {

using TetGradients = std::array<Vec3, 4>;  // ∇N_a, a = 0..3

struct TetGeometry {
  std::vector<Tet> tets;
  std::vector<double> volume;        // V_t > 0
  std::vector<TetGradients> grad;    // Σ_a ∇N_a = 0
  // object.calibration: per_tet: each tet's tensor scales, its level's (MaterialLaw::scales)
  // times its own factors (MaterialLaw::tet_tensors); empty: the level's for every tet. What the
  // stiffness and the damping of the tet take; masses and geometry do not.
  std::vector<StiffnessScales> scales;

  const StiffnessScales& scales_of(int t, const StiffnessScales& level) const {
    return scales.empty() ? level : scales[t];
  }
};

/// Asks for tet t's vertex ids, ∇N, volume and scales ahead of their use: the per-frame passes
/// over a level's live tets (energies, tangent growths) find them cold, the force kernel reading
/// its packed copies (physics/packed_tets.hpp); the energies of liver_probe spent half their
/// time waiting for ∇N. A hint only: the same values. Always inlined: out of line, GCC 12 finds
/// the function without effect (a prefetch has none it models) and deletes its calls.
[[gnu::always_inline]] inline void prefetch_tet(const TetGeometry& geo, int t) {
  const char* g = reinterpret_cast<const char*>(&geo.grad[t]);
  __builtin_prefetch(g);
  __builtin_prefetch(g + sizeof(TetGradients) - 1);
  __builtin_prefetch(&geo.tets[t]);
  __builtin_prefetch(&geo.volume[t]);
  if (!geo.scales.empty()) __builtin_prefetch(&geo.scales[t]);
}
/// How far ahead in a list of tets prefetch_tet() asks.
inline constexpr int kTetPrefetchAhead = 8;

/// Throws std::invalid_argument on a non-positive volume: meshes are checked on load.
/// `law`: its tet_tensors, if any, give TetGeometry::scales (null: none).
TetGeometry build_tet_geometry(const TetMesh& mesh, const MaterialLaw* law = nullptr);

/// Displacement (or velocity) gradient G = Σ_b u_b ∇N_bᵀ of one tet.
inline Mat3 tet_gradient(const TetGradients& g, const Tet& t, const Vec3* u) {
  Mat3 G = u[t[0]] * g[0].transpose();
  G.noalias() += u[t[1]] * g[1].transpose();
  G.noalias() += u[t[2]] * g[2].transpose();
  G.noalias() += u[t[3]] * g[3].transpose();
  return G;
}

}  // namespace mrsim
