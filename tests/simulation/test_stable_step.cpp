// A scenario without time.substeps gets a stable step computed for it (issue 5 point 1, the
// Courant part): the smallest power of two of steps per frame within C h_min / c_p of every
// level that may become active, and a run at that step does not blow up.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "beam_fixture.hpp"
#include "scenario/scenario.hpp"
#include "simulation/stable_step.hpp"

using namespace mrsim;

namespace {

Scenario beam_scenario(int levels_enabled) {
  Scenario sc;
  sc.material.lambda = mrsim::testing::kE * mrsim::testing::kNu /
                       ((1 + mrsim::testing::kNu) * (1 - 2 * mrsim::testing::kNu));
  sc.material.mu = mrsim::testing::kE / (2 * (1 + mrsim::testing::kNu));
  sc.material.density = 1000;
  sc.time.frame_dt = 0.02;
  sc.time.substeps = 0;
  sc.space.enabled = levels_enabled > 1;
  sc.resolved = {{"time", {{"frame_dt", 0.02}}}};
  return sc;
}

}  // namespace

TEST(StableStep, ShortestEdgeOfABoxIsItsSmallestCellSide) {
  EXPECT_NEAR(shortest_edge(make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.06, 0.04), 5, 3, 8)), 0.005,
              1e-15);
}

TEST(StableStep, OmittedSubstepsAreThePowerOfTwoThatKeepsTheFinestLevelStable) {
  const TetMesh coarse = mrsim::testing::beam_mesh(10), fine = mrsim::testing::beam_mesh(20);
  const Scenario sc = beam_scenario(2);
  const Scenario out = with_stable_substeps(sc, {&coarse, &fine});
  const double c = std::sqrt((sc.material.lambda + 2 * sc.material.mu) / 1000);
  const double limit = 0.5 * 0.005 / c;  // finest level: 5 mm edges
  const double dt = 0.02 / out.time.substeps;
  EXPECT_LE(dt, limit);
  EXPECT_GT(2 * dt, limit);  // the smallest such power of two
  EXPECT_EQ(out.time.substeps & (out.time.substeps - 1), 0);
  EXPECT_EQ(out.resolved["time"]["substeps"], out.time.substeps);  // scenario.yaml reruns it
  // Adaptivity off: only level 0 is simulated, the step follows it.
  EXPECT_EQ(with_stable_substeps(beam_scenario(1), {&coarse, &fine}).time.substeps * 2,
            out.time.substeps);
  // Semi-implicit: twice the step (the thesis' claim, measured in tests/time/test_stability).
  Scenario si = sc;
  si.time.integrator = Integrator::SemiImplicit;
  EXPECT_EQ(with_stable_substeps(si, {&coarse, &fine}).time.substeps * 2, out.time.substeps);
  // Given substeps are kept as they are.
  Scenario given = sc;
  given.time.substeps = 7;
  EXPECT_EQ(with_stable_substeps(given, {&coarse, &fine}).time.substeps, 7);
}

TEST(StableStep, TheComputedStepRunsTheBeamWithoutGrowth) {
  // Undamped, the worst case for the explicit scheme: the energy stays bounded over 20 000
  // steps at the computed step (above the real limit it grows by orders of magnitude).
  const TetMesh mesh = mrsim::testing::beam_mesh(20);
  const Scenario out = with_stable_substeps(beam_scenario(1), {&mesh});
  LevelSimulation sim(mesh, mrsim::testing::beam_setup(mesh, Integrator::ModifiedEuler,
                                                        0.02 / out.time.substeps));
  double worst = 0;
  for (int k = 0; k < 20; ++k) {
    sim.advance(1000);
    for (const Vec3& u : sim.state().u) worst = std::max(worst, u.norm());
  }
  EXPECT_LT(worst, 0.02);  // twice the static tip deflection is ~6 mm
}
