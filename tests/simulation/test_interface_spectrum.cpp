// Spectrum of the coupled cross-level operator (docs/hierarchy.md, "coupling"): probe every
// free active DOF with the ghosts refreshed, assemble M⁻¹K_eff from the forces a step computes,
// and look for eigenvalues λ with Im λ ≠ 0 (ü = -λu then grows like exp(Re √-λ · t)). The
// continuous-time system is stable only if every λ is real and ≥ 0.
//
// The thesis' force rule gives growth rates of 170–570 /s after a single split on nested beam
// meshes (measured: splits of coarse points 2, 5, 9), whatever the time step; the
// energy-consistent coupling gives a symmetric K_eff and none.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <complex>

#include "coupled_operator.hpp"
#include "hierarchy/hierarchy_fixture.hpp"
#include "mesh/box_mesh.hpp"
#include "simulation/hierarchical_simulation.hpp"

using namespace mrsim;

namespace {

// The validation beam's material (E = 1 MPa, ν = 0.3), clamped at x = 0.
HierarchySetup clamped_beam_setup(const std::vector<TetMesh>& meshes, Coupling coupling) {
  return mrsim::testing::clamped_setup(meshes, coupling, 576923, 384615,
                                       [](const Vec3& X) { return X.x() < 1e-9; });
}

double max_growth_rate(HierarchicalSimulation& sim, double* asymmetry = nullptr) {
  std::vector<std::pair<int, int>> dofs;
  const Eigen::MatrixXd K = mrsim::testing::coupled_stiffness(sim, dofs);
  if (asymmetry) *asymmetry = (K - K.transpose()).norm() / K.norm();
  Eigen::MatrixXd A = K;
  for (size_t i = 0; i < dofs.size(); ++i)
    A.middleRows(3 * i, 3) /= sim.inertia(dofs[i].first)[dofs[i].second].mass;
  Eigen::EigenSolver<Eigen::MatrixXd> es(A, false);
  double growth = 0;
  for (int i = 0; i < A.rows(); ++i)
    growth = std::max(growth, std::abs(std::sqrt(-es.eigenvalues()[i]).real()));
  return growth;
}

double single_split_growth(int split_point, Coupling coupling, double* asymmetry = nullptr) {
  std::vector<TetMesh> meshes;
  meshes.push_back(make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), 5, 1, 1));
  meshes.push_back(make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), 10, 2, 2));
  HierarchicalSimulation sim({&meshes[0], &meshes[1]}, clamped_beam_setup(meshes, coupling));
  sim.split(0, split_point);
  sim.apply_changes();
  return max_growth_rate(sim, asymmetry);
}

}  // namespace

TEST(InterfaceSpectrum, EnergyCouplingIsSymmetricWithNoGrowingModeAfterASingleSplit) {
  for (Coupling c : {Coupling::Energy, Coupling::EnergyConsistent})
    for (int p : {2, 5, 6, 9}) {
      double asym = 1;
      EXPECT_LT(single_split_growth(p, c, &asym), 1e-6) << "split of coarse point " << p;
      EXPECT_LT(asym, 1e-8) << "split of coarse point " << p;
    }
}

TEST(InterfaceSpectrum, ForceCouplingFluttersAfterASingleSplit) {
  // The thesis' rule, kept as `coupling: force`: the measurement behind docs/hierarchy.md. If
  // this stops failing to be stable, the docs' warning is out of date.
  EXPECT_GT(single_split_growth(5, Coupling::Force), 100.0);
  EXPECT_LT(single_split_growth(6, Coupling::Force), 1e-6);  // a symmetric split is stable
}

TEST(InterfaceSpectrum, EnergyCouplingHasNoGrowingModeOnThreeUnnestedLevels) {
  // Jittered, unrelated meshes (extrapolated ghosts, child-tet-vertex overlaps), a region of
  // every level active at once.
  const auto meshes = mrsim::testing::jittered_box_levels({{3, 1, 1}, {6, 2, 2}, {10, 3, 3}}, 3, 0.2);
  for (Coupling c : {Coupling::Energy, Coupling::EnergyConsistent, Coupling::Force}) {
    HierarchicalSimulation sim({&meshes[0], &meshes[1], &meshes[2]}, clamped_beam_setup(meshes, c));
    for (int l = 0; l < 2; ++l) {
      for (int p : std::vector<int>(sim.lists().active(l)))
        if (sim.model(l).mesh->points[p].x() > 0.04 + 0.02 * l && sim.hierarchy().can_split(l, p))
          sim.split(l, p);
      sim.apply_changes();
    }
    ASSERT_GT(sim.lists().active(2).size(), 0u);
    ASSERT_GT(sim.lists().active(0).size(), 0u);
    const double g = max_growth_rate(sim);
    if (c != Coupling::Force) EXPECT_LT(g, 1e-6);
    else RecordProperty("force_coupling_growth_per_s", std::to_string(g));
  }
}
