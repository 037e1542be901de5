#pragma once
// The coupled cross-level operator of a hierarchy, probed: every free active DOF displaced
// alone, the ghosts refreshed, the forces a step computes read back (K_eff, N/m, of the linear
// Cauchy model). Used by the spectrum and the interface-inertia tests.
#include <Eigen/Dense>
#include <utility>
#include <vector>

#include "hierarchy/hierarchy_fixture.hpp"
#include "simulation/hierarchical_simulation.hpp"

namespace mrsim::testing {

/// A linear (Cauchy) hierarchy with Lamé λ, μ, clamped on the rest points where `fixed(X)`.
template <class Pred>
HierarchySetup clamped_setup(const std::vector<TetMesh>& meshes, Coupling coupling, double lambda,
                             double mu, Pred fixed) {
  HierarchySetup hs;
  hs.law.strain = StrainMeasure::Cauchy;
  hs.law.lambda = lambda;
  hs.law.mu = mu;
  hs.coupling = coupling;
  hs.fixed = fixed_where(meshes, fixed);
  return hs;
}

inline Eigen::MatrixXd coupled_stiffness(HierarchicalSimulation& sim,
                                         std::vector<std::pair<int, int>>& dofs) {
  dofs.clear();
  for (int l = 0; l < sim.num_levels(); ++l)
    for (int p : sim.lists().active(l))
      if (sim.state(l).free_point[p]) dofs.emplace_back(l, p);
  const int n = static_cast<int>(dofs.size());
  Eigen::MatrixXd K(3 * n, 3 * n);
  const double h = 1e-6;
  for (int j = 0; j < 3 * n; ++j) {
    for (int l = 0; l < sim.num_levels(); ++l) {
      for (auto& u : sim.state(l).u) u.setZero();
      for (auto& v : sim.state(l).v) v.setZero();
    }
    sim.state(dofs[j / 3].first).u[dofs[j / 3].second][j % 3] = h;
    sim.refresh_ghosts();
    sim.compute_forces();
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k)
        K(3 * i + k, j) = -sim.state(dofs[i].first).f[dofs[i].second][k] / h;
  }
  return K;
}

}  // namespace mrsim::testing
