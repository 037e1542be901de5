// Restart (issue 18): a simulation taken to a checkpoint at a frame boundary and given back to
// a simulation freshly built from the same setup goes on bit for bit as the original: every
// point's displacement, velocity and force, the active sets, the counters, the time levels,
// with splits and merges on the way, for every integrator. What mrsim run --resume relies on
// (end to end: tests/python/test_resume.py).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "hierarchy/hierarchy_fixture.hpp"
#include "simulation/checkpoint_state.hpp"

using namespace mrsim;

namespace {

struct Case {
  Integrator integrator;
  bool time_levels;
};

class CheckpointState : public ::testing::TestWithParam<Case> {};

std::vector<TetMesh> three_boxes() {
  return mrsim::testing::jittered_box_levels({{4, 3, 2}, {8, 5, 4}, {16, 10, 7}}, 8, 0.15);
}

// A soft box clamped at x = 0, sagging under gravity with a sideways push at the start.
HierarchySetup sagging(const std::vector<TetMesh>& meshes, const Case& c) {
  HierarchySetup hs;
  hs.law.lambda = 5.0e4;
  hs.law.mu = 2.0e4;
  hs.law.density = 1000;
  hs.law.psi = 0.5;
  hs.gravity = Vec3(0, 0, -9.81);
  hs.integrator = c.integrator;
  hs.coupling = Coupling::EnergyConsistent;
  hs.initial_velocity = Vec3(0, 0.05, 0);
  hs.dt = 2.5e-5;
  hs.steps_per_frame = 80;
  for (const TetMesh& m : meshes) {
    std::vector<std::uint8_t> fixed(m.points.size(), 0);
    for (size_t i = 0; i < m.points.size(); ++i) fixed[i] = m.points[i].x() < 1e-9;
    hs.fixed.push_back(fixed);
  }
  if (c.time_levels) {
    TimeLevelRules rules;
    rules.frame_dt = hs.dt * hs.steps_per_frame;
    rules.max_level = 8;
    rules.semi_implicit = is_semi_implicit(c.integrator);
    hs.time_levels = rules;
  }
  return hs;
}

SpaceAdaptivitySettings adaptive() {
  SpaceAdaptivitySettings s;
  s.enabled = true;
  s.refine_above = 2e-4;
  s.coarsen_below = 1.9e-4;
  s.min_dwell_frames = 2;
  s.calm_frames = 3;  // the calm streaks are part of the state
  return s;
}

void advance(HierarchicalSimulation& sim, SpaceAdaptivity& adapt, int from, int to,
             std::int64_t& splits) {
  std::vector<HierarchyEvent> events;
  for (int frame = from; frame < to; ++frame) {
    sim.advance_frame();
    adapt.update(sim, frame, events);
  }
  for (const HierarchyEvent& e : events) splits += e.kind == "split";
}

void expect_bitwise_equal(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const char* what,
                          int l) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i)
    ASSERT_TRUE(a[i] == b[i]) << what << " of point " << i << " of level " << l << ": "
                              << a[i].transpose() << " vs " << b[i].transpose();
}

TEST_P(CheckpointState, ARestoredSimulationGoesOnBitForBit) {
  const Case c = GetParam();
  const auto meshes = three_boxes();
  const std::vector<const TetMesh*> levels{&meshes[0], &meshes[1], &meshes[2]};
  HierarchicalSimulation original(levels, sagging(meshes, c));
  SpaceAdaptivity original_adapt(adaptive(), original);
  std::int64_t splits_before = 0, splits_after = 0, ignored = 0;
  // The checkpoint is taken at the first frame end with a refined hierarchy and a calm streak
  // under way (merges pending on calm_frames), so both must come back.
  auto streak_under_way = [&] {
    for (const auto& level : original_adapt.calm_streaks())
      for (int n : level)
        if (n > 0) return true;
    return false;
  };
  int at = 0;
  while (at < 16 && !(splits_before > 0 && streak_under_way())) {
    advance(original, original_adapt, at, at + 1, splits_before);
    ++at;
  }
  ASSERT_GT(splits_before, 0) << "the checkpoint must hold a refined hierarchy";
  ASSERT_TRUE(streak_under_way()) << "the checkpoint must hold a calm streak under way";
  const SimulationCheckpoint checkpoint = take_checkpoint(original, original_adapt);
  advance(original, original_adapt, at, at + 4, splits_after);

  HierarchicalSimulation resumed(levels, sagging(meshes, c));
  SpaceAdaptivity resumed_adapt(adaptive(), resumed);
  restore_checkpoint(checkpoint, resumed, resumed_adapt);
  for (int l = 0; l < 3; ++l)
    EXPECT_EQ(resumed_adapt.calm_streaks()[l], checkpoint.levels[l].calm_streak) << "level " << l;
  advance(resumed, resumed_adapt, at, at + 4, ignored);

  EXPECT_EQ(original.time(), resumed.time());
  EXPECT_EQ(original.steps(), resumed.steps());
  EXPECT_EQ(original_adapt.calm_streaks(), resumed_adapt.calm_streaks());
  for (int l = 0; l < 3; ++l) {
    EXPECT_EQ(original.lists().active(l), resumed.lists().active(l)) << "level " << l;
    EXPECT_EQ(original.force_evaluations(l), resumed.force_evaluations(l)) << "level " << l;
    EXPECT_EQ(original.tet_updates(l), resumed.tet_updates(l)) << "level " << l;
    expect_bitwise_equal(original.state(l).u, resumed.state(l).u, "u", l);
    expect_bitwise_equal(original.state(l).v, resumed.state(l).v, "v", l);
    expect_bitwise_equal(original.state(l).f, resumed.state(l).f, "f", l);
  }
  if (c.time_levels) {
    EXPECT_EQ(original.time_levels()->evaluations(), resumed.time_levels()->evaluations());
    EXPECT_EQ(original.time_levels()->particles_per_level(),
              resumed.time_levels()->particles_per_level());
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, CheckpointState,
                         ::testing::Values(Case{Integrator::ModifiedEuler, false},
                                           Case{Integrator::StoermerVerlet, false},
                                           Case{Integrator::SemiImplicit, false},
                                           Case{Integrator::ModifiedEuler, true}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::string(integrator_name(info.param.integrator)) +
                                  (info.param.time_levels ? "_time_levels" : "");
                         });

TEST(CheckpointState, ACheckpointOfAnotherHierarchyIsRefused) {
  const auto meshes = three_boxes();
  const Case c{Integrator::ModifiedEuler, false};
  HierarchicalSimulation sim({&meshes[0], &meshes[1], &meshes[2]}, sagging(meshes, c));
  SpaceAdaptivity adapt(adaptive(), sim);
  SimulationCheckpoint checkpoint = take_checkpoint(sim, adapt);
  HierarchicalSimulation two({&meshes[0], &meshes[1]}, sagging(meshes, c));
  SpaceAdaptivity two_adapt(adaptive(), two);
  EXPECT_THROW(restore_checkpoint(checkpoint, two, two_adapt), std::invalid_argument);
  // Counters that no sequence of splits and merges can make: a finest point active with no
  // parent subdivided.
  checkpoint.levels[2].active_ref[0] = 1;
  EXPECT_THROW(restore_checkpoint(checkpoint, sim, adapt), std::runtime_error);
  checkpoint = take_checkpoint(sim, adapt);
  checkpoint.levels[1].u.pop_back();
  EXPECT_THROW(restore_checkpoint(checkpoint, sim, adapt), std::invalid_argument);
}

}  // namespace
