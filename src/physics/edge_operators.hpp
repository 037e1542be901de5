#pragma once
// The λ/μ-independent edge matrices of method.md §2.2 [Eng]: per CSR entry (i, j)
//   A_ij = Σ_t V_t ∇N_i ∇N_jᵀ,   B_ij = Σ_t V_t (∇N_j ∇N_iᵀ + (∇N_i·∇N_j) I),
// so that K_ij = λA_ij + μB_ij (stiffness) and D_ij = φA_ij + ψB_ij (damping), and the linear
// force is f_i = -Σ_j K_ij (u_j - u_i) - Σ_j D_ij (v_j - v_i).
#include <array>
#include <vector>

#include "physics/material_law.hpp"
#include "physics/point_adjacency.hpp"
#include "physics/tet_geometry.hpp"

namespace mrsim {

struct CombinedEdges {
  std::vector<std::vector<Mat3>> matrices;  // one per coefficient pair, indexed like nbr
  std::vector<double> laplacian_w;          // -tr(B_ij) / 4 = -Σ_t V_t ∇N_i·∇N_j (§3.1)
};

/// a·A + b·B for each pair (a, b) of `coefficients` (stiffness λ, μ; damping φ, ψ) and the
/// Laplacian weights of every CSR entry, A and B summed one point's row at a time: they are
/// never held whole (two more arrays the size of K, written and read once). No coefficients:
/// the Laplacian weights alone, the same bits, at a fraction of the cost.
CombinedEdges combined_edge_operators(const TetGeometry& geo, const PointAdjacency& adj,
                                      const std::vector<std::array<double, 2>>& coefficients);

/// Block (a, b) of V Bᵀ C B for the tensor S_pq = λ tr(ε) δ_pq + 2 μ_pq ε_pq:
///   [p][r] = V (λ g_ap g_br + δ_pr Σ_q μ_pq g_aq g_bq + μ_pr g_bp g_ar),
/// which is λA + μB's block when every μ_pq = μ.
Mat3 orthotropic_block(const Vec3& ga, const Vec3& gb, double volume, double lambda,
                       const double (&mu)[3][3]);

/// λ and μ_pq of λ, μ under `scales`, as hooke() scales them: what orthotropic_block() takes.
struct OrthotropicTensor {
  double lambda;
  double mu[3][3];
};
OrthotropicTensor orthotropic_tensor(double lambda, double mu, const StiffnessScales& scales);

/// K_ij (or D_ij) of a calibrated level's orthotropic tensor (MaterialLaw::scales, or each tet's
/// TetGeometry::scales when it has them): λ and μ scaled as hooke() does. Equal to
/// combined_edge_operators() with (λ, μ) to rounding when the scales are all one (the isotropic
/// law keeps combined_edge_operators()).
std::vector<Mat3> orthotropic_edge_matrices(const TetGeometry& geo, const PointAdjacency& adj,
                                            double lambda, double mu,
                                            const StiffnessScales& scales);

/// Diagonal block K_ii = -Σ_j K_ij (translations produce no force).
Mat3 diagonal_block(const std::vector<Mat3>& k_edges, const PointAdjacency& adj, int i);

}  // namespace mrsim
