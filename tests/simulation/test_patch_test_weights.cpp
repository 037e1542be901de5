// The cross-level patch test on real, independently meshed levels (the bundled liver, four
// levels of 20 to 3386 points): wherever splits put interfaces, a linear displacement field
// leaves no force on any interior active point, and every interface weight stays positive.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "mesh/boundary_faces.hpp"
#include "mesh/mesh_reader.hpp"
#include "simulation/hierarchical_simulation.hpp"

namespace mrsim {
namespace {

std::vector<TetMesh> liver_levels() {
  std::vector<TetMesh> m;
  for (int l = 0; l < 4; ++l)
    m.push_back(read_tet_mesh(std::filesystem::path(MRSIM_SOURCE_DIR) / "scenarios" / "meshes" /
                                  ("liver_L" + std::to_string(l) + ".vtu"),
                              LengthUnit::Metre));
  return m;
}

// Largest force on an interior / surface active point under u = A X (ghosts refreshed).
std::pair<double, double> linear_field_forces(HierarchicalSimulation& sim,
                                              const std::vector<std::vector<std::uint8_t>>& skin) {
  Mat3 A;
  A << 1e-3, 2e-4, -3e-4, 5e-4, -2e-3, 1e-4, -4e-4, 3e-4, 1.5e-3;
  for (int l = 0; l < sim.num_levels(); ++l)
    for (int p : sim.lists().active(l)) sim.state(l).u[p] = A * sim.model(l).mesh->points[p];
  sim.refresh_ghosts();
  sim.compute_forces();
  double interior = 0, surface = 0;
  for (int l = 0; l < sim.num_levels(); ++l)
    for (int p : sim.lists().active(l)) {
      double& x = skin[l][p] ? surface : interior;
      x = std::max(x, sim.state(l).f[p].norm());
    }
  return {interior, surface};
}

TEST(PatchTestWeights, LiverLevelsPassTheCrossLevelPatchTestWhereverTheyAreSplit) {
  const std::vector<TetMesh> meshes = liver_levels();
  std::vector<std::vector<std::uint8_t>> skin;
  for (const TetMesh& m : meshes) {
    skin.emplace_back(m.points.size(), std::uint8_t{0});
    for (const Face& f : boundary_faces(m))
      for (int p : f) skin.back()[p] = 1;
  }
  for (StrainMeasure strain : {StrainMeasure::Cauchy, StrainMeasure::GreenLagrange}) {
    HierarchySetup s;
    s.coupling = Coupling::EnergyConsistent;
    s.law.strain = strain;
    s.law.lambda = 5.0e4;
    s.law.mu = 1.0e4;
    s.law.psi = 2;
    HierarchicalSimulation sim({&meshes[0], &meshes[1], &meshes[2], &meshes[3]}, s);
    std::mt19937 rng(7);
    double worst = 0, worst_residual = 0;
    int held = 0, solved = 0;
    double largest = 0;
    for (int round = 0; round < 12; ++round) {
      // Split a random third of the splittable points of a random level, or merge some back.
      const int l = std::uniform_int_distribution<int>(0, 2)(rng);
      std::vector<int> candidates(sim.lists().active(l));
      for (int p : candidates) {
        if (std::uniform_real_distribution<double>(0, 1)(rng) > 0.35) continue;
        if (round % 4 == 3 && sim.hierarchy().can_merge(l, p))
          sim.merge(l, p);
        else if (sim.hierarchy().can_split(l, p))
          sim.split(l, p);
      }
      sim.apply_changes();
      const auto [interior, surface] = linear_field_forces(sim, skin);
      worst = std::max(worst, interior / surface);
      worst_residual = std::max(worst_residual, sim.patch_test().residual_after);
      held += sim.patch_test().held;
      largest = std::max(largest, sim.patch_test().largest_ratio);
      solved += sim.patch_test().band_tets;
    }
    std::printf("liver, %s: 12 random split/merge rounds, interior force at most %.1e of the "
                "surface's, weight residual %.1e, %d of %d weights held at their floor, largest weight/share %.2f\n",
                strain == StrainMeasure::Cauchy ? "Cauchy" : "Green", worst, worst_residual, held,
                solved, largest);
    EXPECT_LT(worst, 1e-8);
    EXPECT_LT(worst_residual, 1e-8);
  }
}

}  // namespace
}  // namespace mrsim
