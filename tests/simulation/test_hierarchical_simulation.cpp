// The multiresolution model in motion (issue 4 point 6): forces across level interfaces, and
// the limits where it must coincide with a single mesh.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "hierarchy/hierarchy_fixture.hpp"
#include "simulation/hierarchical_simulation.hpp"
#include "simulation/level_simulation.hpp"

using namespace mrsim;

namespace {

struct Box3 {
  std::vector<TetMesh> meshes;
  Box3() : meshes(mrsim::testing::jittered_box_levels({{3, 2, 2}, {6, 4, 3}, {12, 7, 5}}, 8, 0.2)) {}
  static bool interior(const Vec3& p) {
    return p.x() > 1e-9 && p.x() < 0.1 - 1e-9 && p.y() > 1e-9 && p.y() < 0.06 - 1e-9 &&
           p.z() > 1e-9 && p.z() < 0.04 - 1e-9;
  }
  std::vector<const TetMesh*> ptrs() const { return {&meshes[0], &meshes[1], &meshes[2]}; }
};

HierarchySetup setup(StrainMeasure s) {
  HierarchySetup h;
  h.law.strain = s;
  h.law.lambda = 5.0e4;
  h.law.mu = 2.0e4;
  h.law.psi = 5;
  h.dt = 1e-5;
  return h;
}

// Split a random region around a point so that all three levels are active somewhere.
void split_region(HierarchicalSimulation& sim, const Vec3& centre, double radius) {
  for (int l = 0; l + 1 < sim.num_levels(); ++l) {
    for (int p : std::vector<int>(sim.lists().active(l)))
      if ((sim.model(l).mesh->points[p] - centre).norm() < radius &&
          sim.hierarchy().can_split(l, p))
        sim.split(l, p);
    sim.apply_changes();
    radius *= 0.6;
  }
}

std::vector<Vec3> active_forces(HierarchicalSimulation& sim, int l, const Vec3& gravity) {
  LevelForceField field(sim.model(l), gravity);
  field.serve(&sim.lists().active(l));
  std::vector<Vec3> f(sim.model(l).num_points(), Vec3::Zero());
  field.evaluate(sim.state(l).u.data(), sim.state(l).v.data(), f.data());
  return f;
}

class BothStrains : public ::testing::TestWithParam<StrainMeasure> {};

}  // namespace

TEST_P(BothStrains, MixedLevelsCoverTheBodyAndLinearFieldsGiveNoInterfaceForce) {
  const Box3 box;
  HierarchicalSimulation sim(box.ptrs(), setup(GetParam()));
  split_region(sim, Vec3(0.05, 0.03, 0.02), 0.03);
  ASSERT_TRUE(sim.hierarchy().check_invariants().empty());
  for (int l = 1; l < 3; ++l) ASSERT_GT(sim.lists().active(l).size(), 0u) << l;
  ASSERT_GT(sim.lists().active(0).size(), 0u);
  // Cross-level patch test: active points hold a linear field; ghosts interpolate it; every
  // interior active point — including those whose neighbours are ghosts — feels no force.
  Mat3 A;
  A << 1e-3, 2e-4, -3e-4, 5e-4, -2e-3, 1e-4, -4e-4, 3e-4, 1.5e-3;
  for (int l = 0; l < 3; ++l)
    for (int p : sim.lists().active(l)) sim.state(l).u[p] = A * sim.model(l).mesh->points[p];
  sim.refresh_ghosts();
  double worst = 0, boundary = 0;
  int interface_points = 0;
  for (int l = 0; l < 3; ++l) {
    const auto f = active_forces(sim, l, Vec3::Zero());
    for (int p : sim.lists().active(l)) {
      const bool in = Box3::interior(sim.model(l).mesh->points[p]);
      (in ? worst : boundary) = std::max(in ? worst : boundary, f[p].norm());
      const auto& adj = sim.model(l).adj;
      for (int e = adj.nbr_start[p]; e < adj.nbr_start[p + 1]; ++e)
        if (sim.hierarchy().state(l, adj.nbr[e]) != NodeState::Active) {
          interface_points += in;
          break;
        }
    }
  }
  EXPECT_GT(interface_points, 10);
  EXPECT_LT(worst, 1e-9 * boundary);
  EXPECT_GT(boundary, 0.0);
}

TEST_P(BothStrains, RigidTranslationOfAMixedLevelBodyGivesNoForce) {
  const Box3 box;
  HierarchicalSimulation sim(box.ptrs(), setup(GetParam()));
  split_region(sim, Vec3(0.02, 0.02, 0.02), 0.04);
  for (int l = 0; l < 3; ++l)
    for (int p : sim.lists().active(l)) {
      sim.state(l).u[p] = Vec3(0.01, -0.02, 0.005);
      sim.state(l).v[p] = Vec3(1, 2, 3);
    }
  sim.refresh_ghosts();
  for (int l = 0; l < 3; ++l) {
    const auto f = active_forces(sim, l, Vec3::Zero());
    for (int p : sim.lists().active(l)) EXPECT_LT(f[p].norm(), 1e-12) << l << " " << p;
  }
}

INSTANTIATE_TEST_SUITE_P(Strain, BothStrains,
                         ::testing::Values(StrainMeasure::Cauchy, StrainMeasure::GreenLagrange));

TEST(HierarchicalSimulation, EverythingSplitIsTheFinestMeshAlone) {
  const Box3 box;
  HierarchySetup hs = setup(StrainMeasure::GreenLagrange);
  hs.gravity = Vec3(0, 0, -9.81);
  hs.fixed.resize(3);
  for (int l = 0; l < 3; ++l) {
    hs.fixed[l].assign(box.meshes[l].points.size(), 0);
    for (size_t i = 0; i < box.meshes[l].points.size(); ++i)
      hs.fixed[l][i] = box.meshes[l].points[i].x() < 1e-12;
  }
  HierarchicalSimulation sim(box.ptrs(), hs);
  for (int l = 0; l < 2; ++l) {
    for (int p = 0; p < sim.model(l).num_points(); ++p)
      if (sim.hierarchy().can_split(l, p)) sim.split(l, p);
    sim.apply_changes();
  }
  ASSERT_EQ(sim.lists().active(2).size(), box.meshes[2].points.size());
  ASSERT_TRUE(sim.lists().active(0).empty());
  LevelSetup ls;
  ls.law = hs.law;
  ls.gravity = hs.gravity;
  ls.dt = hs.dt;
  ls.fixed = hs.fixed[2];
  LevelSimulation ref(box.meshes[2], ls);
  sim.advance(200);
  ref.advance(200);
  const auto& a = sim.state(2).u;
  const auto& b = ref.state().u;
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)), 0);
  EXPECT_GT(b.back().norm(), 0.0);
}

TEST(HierarchicalSimulation, NeverSplitIsTheCoarsestMeshAlone) {
  const Box3 box;
  HierarchySetup hs = setup(StrainMeasure::Cauchy);
  hs.gravity = Vec3(0, 0, -9.81);
  HierarchicalSimulation sim(box.ptrs(), hs);
  LevelSetup ls;
  ls.law = hs.law;
  ls.gravity = hs.gravity;
  ls.dt = hs.dt;
  LevelSimulation ref(box.meshes[0], ls);
  sim.advance(100);
  ref.advance(100);
  EXPECT_EQ(std::memcmp(sim.state(0).u.data(), ref.state().u.data(),
                        ref.state().u.size() * sizeof(Vec3)),
            0);
  EXPECT_EQ(sim.force_evaluations(1), 0);  // finer levels cost nothing while inactive
  EXPECT_EQ(sim.force_evaluations(2), 0);
}
