// Spectrum of the coupled cross-level operator (docs/hierarchy.md, "interface flutter"):
// probe every free active DOF with the ghosts refreshed, assemble M⁻¹K_eff, and look for
// eigenvalues λ with Im λ ≠ 0 (ü = -λu then grows like exp(Re √-λ · t)). The continuous-time
// system is stable only if every λ is real and ≥ 0.
//
// DISABLED: today a single split on nested beam meshes gives growth rates of 170–570 /s
// (measured: splits of coarse points 2, 5, 9). Enable it as the acceptance check of the fix.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <complex>

#include "mesh/box_mesh.hpp"
#include "simulation/hierarchical_simulation.hpp"

using namespace mrsim;

namespace {

double max_growth_rate(int split_point) {
  std::vector<TetMesh> meshes;
  meshes.push_back(make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), 5, 1, 1));
  meshes.push_back(make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), 10, 2, 2));
  HierarchySetup hs;
  hs.law.strain = StrainMeasure::Cauchy;
  hs.law.lambda = 576923;
  hs.law.mu = 384615;
  hs.fixed.resize(2);
  for (int l = 0; l < 2; ++l) {
    hs.fixed[l].assign(meshes[l].points.size(), 0);
    for (size_t i = 0; i < meshes[l].points.size(); ++i)
      hs.fixed[l][i] = meshes[l].points[i].x() < 1e-9;
  }
  HierarchicalSimulation sim({&meshes[0], &meshes[1]}, hs);
  sim.split(0, split_point);
  sim.apply_changes();
  std::vector<std::pair<int, int>> dofs;
  for (int l = 0; l < 2; ++l)
    for (int p : sim.lists().active(l))
      if (sim.state(l).free_point[p]) dofs.emplace_back(l, p);
  const int n = static_cast<int>(dofs.size());
  Eigen::MatrixXd A(3 * n, 3 * n);
  const double h = 1e-6;
  for (int j = 0; j < 3 * n; ++j) {
    for (int l = 0; l < 2; ++l) {
      for (auto& u : sim.state(l).u) u.setZero();
      for (auto& v : sim.state(l).v) v.setZero();
    }
    sim.state(dofs[j / 3].first).u[dofs[j / 3].second][j % 3] = h;
    sim.refresh_ghosts();
    for (int l = 0; l < 2; ++l) {
      LevelForceField field(sim.model(l), Vec3::Zero());
      field.serve(&sim.lists().active(l));
      std::vector<Vec3> f(sim.model(l).num_points(), Vec3::Zero());
      field.evaluate(sim.state(l).u.data(), sim.state(l).v.data(), f.data());
      for (int i = 0; i < n; ++i)
        if (dofs[i].first == l)
          for (int k = 0; k < 3; ++k)
            A(3 * i + k, j) = -f[dofs[i].second][k] / h / sim.model(l).mass[dofs[i].second];
    }
  }
  Eigen::EigenSolver<Eigen::MatrixXd> es(A, false);
  double growth = 0;
  for (int i = 0; i < 3 * n; ++i)
    growth = std::max(growth, std::abs(std::sqrt(-es.eigenvalues()[i]).real()));
  return growth;
}

}  // namespace

TEST(InterfaceSpectrum, DISABLED_SingleSplitGivesNoGrowingMode) {
  for (int p : {2, 5, 9}) EXPECT_LT(max_growth_rate(p), 1e-6) << "split of coarse point " << p;
}

TEST(InterfaceSpectrum, SymmetricSplitIsStableAndTheProbeWorks) {
  // Point 6 of the coarse beam gives a real spectrum today: a regression guard for the probe
  // and for the configurations that are already stable.
  EXPECT_LT(max_growth_rate(6), 1e-6);
}
