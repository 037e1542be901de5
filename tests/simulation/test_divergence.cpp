// The divergence message (issue 15 point 4): it names the level and the point, where the point
// sits in the hierarchy (the usual culprit: a coarse point next to the fine region), and its
// step against its stable step estimate and the smallest in force, so that a user knows what to
// change.
#include <gtest/gtest.h>

#include <cmath>

#include "hierarchy/hierarchy_fixture.hpp"
#include "simulation/divergence.hpp"

using namespace mrsim;

namespace {

HierarchySetup setup(double dt) {
  HierarchySetup hs;
  hs.law.lambda = 5e4;
  hs.law.mu = 1e4;
  hs.dt = dt;
  return hs;
}

}  // namespace

TEST(Divergence, MessageNamesThePlaceAndTheStepAgainstTheEstimate) {
  const auto meshes = mrsim::testing::jittered_box_levels({{3, 2, 2}, {6, 4, 3}}, 5, 0.2);
  HierarchicalSimulation sim({&meshes[0], &meshes[1]}, setup(1e-2));
  sim.split(0, 0);
  sim.apply_changes();
  // An active coarse point with a subdivided neighbour.
  const PointAdjacency& adj = sim.model(0).adj;
  int coarse = -1;
  for (int p : sim.lists().active(0))
    for (int e = adj.nbr_start[p]; e < adj.nbr_start[p + 1] && coarse < 0; ++e)
      if (sim.hierarchy().state(0, adj.nbr[e]) == NodeState::GhostSub) coarse = p;
  ASSERT_GE(coarse, 0);
  sim.state(0).v[coarse].x() = NAN;
  const DivergenceGuard guard = DivergenceGuard::for_level(sim.model(0), 1.0);
  const auto why = guard.check(sim, 0.0);
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("point " + std::to_string(coarse) + " of level 0"), std::string::npos)
      << *why;
  EXPECT_NE(why->find("a coarse point next to the fine region"), std::string::npos) << *why;
  EXPECT_NE(why->find("against its stable step estimate"), std::string::npos) << *why;
  // 10 ms is far above this point's estimate: the message says so and what to do.
  EXPECT_GT(1e-2, 2 * sim.stable_steps(0)[coarse]);
  EXPECT_NE(why->find("stable step estimate in force"), std::string::npos) << *why;
  EXPECT_NE(why->find("a step is above its estimate"), std::string::npos) << *why;
  EXPECT_NE(why->find("raise time.substeps"), std::string::npos) << *why;
}

// The first non-finite point is the first in list order, anywhere once a blow-up has spread:
// the advice follows the point whose step is furthest above its estimate, and names it.
TEST(Divergence, NonFiniteMessageNamesThePointAboveItsEstimate) {
  const auto meshes = mrsim::testing::jittered_box_levels({{4, 3, 3}}, 5, 0.3);
  const HierarchicalSimulation probe({&meshes[0]}, setup(1e-6));
  const std::vector<double>& estimates = probe.stable_steps(0);
  int calm = -1;  // a free point with the largest estimate
  for (int p : probe.lists().active(0))
    if (probe.state(0).free_point[p] && (calm < 0 || estimates[p] > estimates[calm])) calm = p;
  const double in_force = probe.stable_step_in_force().dt;
  ASSERT_LT(1.2 * in_force, estimates[calm]);
  // A step above the smallest estimate, below the calm point's own.
  HierarchicalSimulation sim({&meshes[0]}, setup(std::sqrt(in_force * estimates[calm])));
  sim.state(0).u[calm].y() = INFINITY;
  const DivergenceGuard guard = DivergenceGuard::for_level(sim.model(0), 1.0);
  const auto why = guard.check(sim, 0.0);
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("point " + std::to_string(calm) + " of level 0"), std::string::npos) << *why;
  const std::string culprit =
      "at point " + std::to_string(sim.stable_step_in_force().point) + " of level 0): raise";
  EXPECT_NE(why->find(culprit), std::string::npos) << *why;
  EXPECT_EQ(why->find("within its estimate"), std::string::npos) << *why;
}

// Every step within its estimate: the advice is about the load, not the step.
TEST(Divergence, NonFiniteMessageWithinTheEstimatesBlamesTheLoad) {
  const auto meshes = mrsim::testing::jittered_box_levels({{3, 2, 2}}, 5, 0.2);
  HierarchicalSimulation sim({&meshes[0]}, setup(1e-7));
  const int p = sim.lists().active(0).back();
  sim.state(0).v[p].z() = NAN;
  const auto why = DivergenceGuard::for_level(sim.model(0), 1.0).check(sim, 0.0);
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("every step is within its estimate"), std::string::npos) << *why;
  EXPECT_EQ(why->find("raise time.substeps"), std::string::npos) << *why;
}

TEST(Divergence, EnergyMessageNamesTheStableStepInForce) {
  const auto meshes = mrsim::testing::jittered_box_levels({{3, 2, 2}}, 5, 0.2);
  HierarchicalSimulation sim({&meshes[0]}, setup(1e-6));
  const DivergenceGuard guard = DivergenceGuard::for_level(sim.model(0), 1.0);
  const auto why = guard.check(sim, 2 * guard.energy_bound);
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("stable step estimate in force"), std::string::npos) << *why;
  EXPECT_NE(why->find("inside level 0's region"), std::string::npos) << *why;
  // 1 µs is within the estimate: raising the substeps would not help, and the advice says so.
  EXPECT_LT(sim.step(), sim.stable_step_in_force().dt);
  EXPECT_NE(why->find("the step is within it"), std::string::npos) << *why;
  EXPECT_EQ(why->find("raise time.substeps"), std::string::npos) << *why;
  EXPECT_NE(why->find("or use time.integrator: semi_implicit"), std::string::npos) << *why;
}

TEST(Divergence, EnergyMessageAboveTheEstimateAndAlreadySemiImplicit) {
  const auto meshes = mrsim::testing::jittered_box_levels({{3, 2, 2}}, 5, 0.2);
  HierarchySetup hs = setup(1e-1);
  hs.integrator = Integrator::SemiImplicit;
  HierarchicalSimulation sim({&meshes[0]}, hs);
  const DivergenceGuard guard = DivergenceGuard::for_level(sim.model(0), 1.0);
  const auto why = guard.check(sim, 2 * guard.energy_bound);
  ASSERT_TRUE(why.has_value());
  EXPECT_GT(sim.step(), sim.stable_step_in_force().dt);
  EXPECT_NE(why->find("the step is above it: raise time.substeps"), std::string::npos) << *why;
  // It is semi-implicit already: no advice to switch to it.
  EXPECT_EQ(why->find("semi_implicit"), std::string::npos) << *why;
}
