#pragma once
// The linear (Cauchy) stiffness of a level split by the seven coefficients of an orthotropic
// tensor (MaterialLaw::scales): K(s) = Σ_j s_j K_j, with K_0 the λ part and K_1..K_6 the μ
// parts of the strain components xx, yy, zz, yz, xz, xy; with seven more factors per tet
// (MaterialLaw::tet_tensors), K(s, q) = Σ_t Σ_j s_j q_tj K_tj. Restricted to the free degrees of
// freedom (3 per point that is not fixed). Used by the calibration of coarse levels
// (hierarchy/level_calibration.hpp), at set-up only.
#include <Eigen/Sparse>
#include <array>
#include <cstdint>
#include <vector>

#include "physics/material_law.hpp"
#include "physics/tet_geometry.hpp"

namespace mrsim {

using SparseMatrix = Eigen::SparseMatrix<double>;
using ComponentValues = std::array<double, 7>;

struct ComponentStiffness {
  std::array<SparseMatrix, 7> parts;  // same sparsity pattern, free DoFs only
  Eigen::VectorXd mass;               // lumped mass per free DoF (kg)
  std::vector<int> dof_of_point;      // first free DoF of each point, -1 when fixed
  TetGeometry geo;                    // the level's tets (the per-tet terms)
  double lambda = 0, mu = 0;          // Pa, the law's

  int free_dofs() const { return static_cast<int>(mass.size()); }
  int num_tets() const { return static_cast<int>(geo.tets.size()); }
  /// Σ_j scales_j parts_j.
  SparseMatrix combined(const std::array<double, 7>& scales) const;
  /// Σ_t Σ_j scales_j tets_tj K_tj (assembled again: set-up, coarse levels).
  SparseMatrix combined(const std::array<double, 7>& scales, const TetTensors& tets) const;
  /// aᵀ K_tj b of every tet t and component j (a, b over the free DoFs): the terms whose sums
  /// are aᵀ parts_j b. What the derivatives of a per-tet fit need, in one pass over the tets.
  std::vector<ComponentValues> tet_terms(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;
};

/// `fixed`: one flag per point (empty = none fixed). λ, μ and density of `law` (its scales
/// ignored).
ComponentStiffness component_stiffness(const TetGeometry& geo, int num_points,
                                       const MaterialLaw& law,
                                       const std::vector<std::uint8_t>& fixed);

}  // namespace mrsim
