#pragma once
// The coupled cross-level operator of a hierarchy, probed: every free active DOF displaced
// alone, the ghosts refreshed, the forces a step computes read back (K_eff, N/m, of the linear
// Cauchy model), and its eigenvalues with the masses the step uses. Used by the spectrum,
// interface-inertia and mixed-partition tests.
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <utility>
#include <vector>

#include "hierarchy/hierarchy_fixture.hpp"
#include "hierarchy/level_calibration.hpp"
#include "scenario/material.hpp"
#include "simulation/hierarchical_simulation.hpp"
#include "support/bundled_levels.hpp"

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

/// The linear (Cauchy) law of Young's modulus `young` and Poisson ratio `poisson`.
inline MaterialLaw cauchy_law(double young, double poisson) {
  const scenario::LameParameters lame = scenario::lame_from_engineering({young, poisson});
  MaterialLaw law;
  law.strain = StrainMeasure::Cauchy;
  law.lambda = lame.lambda;
  law.mu = lame.mu;
  return law;
}

/// The last `levels` levels of a bundled hierarchy, each with its calibrated law, held where
/// the bundle holds them.
inline HierarchySetup calibrated_setup(const test_support::BundledLevels& b,
                                       const MaterialLaw& law,
                                       const std::vector<LevelCalibration>& cal,
                                       Coupling coupling, int levels) {
  HierarchySetup hs;
  hs.law = law;
  hs.coupling = coupling;
  hs.fixed.assign(b.fixed.end() - levels, b.fixed.end());
  const int L = static_cast<int>(b.meshes.size());
  for (int l = L - levels; l < L; ++l) hs.level_laws.push_back(cal[l].applied_to(law));
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

/// The eigenvalues ω² of the current configuration's coupled operator, with the masses the
/// step uses (M^-1/2 K M^-1/2, K symmetrized), ascending.
inline Eigen::VectorXd coupled_w2(HierarchicalSimulation& sim) {
  std::vector<std::pair<int, int>> dofs;
  Eigen::MatrixXd K = coupled_stiffness(sim, dofs);
  K = 0.5 * (K + K.transpose());
  Eigen::VectorXd s(K.rows());
  for (int i = 0; i < K.rows(); ++i)
    s[i] = 1.0 / std::sqrt(sim.inertia(dofs[i / 3].first)[dofs[i / 3].second].mass);
  const Eigen::MatrixXd A = s.asDiagonal() * K * s.asDiagonal();
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A, Eigen::EigenvaluesOnly).eigenvalues();
}

}  // namespace mrsim::testing
