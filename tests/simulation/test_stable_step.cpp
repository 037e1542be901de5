// A scenario without time.substeps gets a stable step computed for it (issue 5 point 1, issue
// 15 point 2): the fewest steps per frame (a power of two with time levels) within the per-point stable step
// estimate of every level that may become active (cells, damping, the tools' contact), a run at
// that step does not blow up, and one that would need more than 2^30 steps is an input error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "beam_fixture.hpp"
#include "core/error.hpp"
#include "physics/level_model.hpp"
#include "scenario/scenario.hpp"
#include "simulation/hierarchical_simulation.hpp"
#include "simulation/level_setup_from_scenario.hpp"
#include "simulation/stable_step.hpp"
#include "time/steps_per_frame.hpp"

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
  // The material as given on both levels: the coarse level's own step is then the plain
  // mesh's (level_estimate), not that of a fit that stiffens some of its tets.
  sc.calibration = CalibrationKind::None;
  sc.resolved = {{"time", {{"frame_dt", 0.02}}}};
  return sc;
}

}  // namespace

TEST(StableStep, ShortestEdgeOfABoxIsItsSmallestCellSide) {
  EXPECT_NEAR(shortest_edge(make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.06, 0.04), 5, 3, 8)), 0.005,
              1e-15);
}

// The smallest per-point estimate of a mesh alone (whole stars, no contact), calibrated by
// its spectrum as for one global step (physics/spectral_bound.hpp).
double level_estimate(const TetMesh& mesh, const Scenario& sc, bool semi = false) {
  const LevelModel m = build_level_model(mesh, material_law(sc.material));
  double dt = INFINITY;
  for (const PointInertia& p : m.star) dt = std::min(dt, stable_step_of(calibrated(p, m), semi));
  return dt;
}

TEST(StableStep, OmittedSubstepsAreTheFewestThatKeepTheFinestLevelStable) {
  const TetMesh coarse = mrsim::testing::beam_mesh(10), fine = mrsim::testing::beam_mesh(20);
  const Scenario sc = beam_scenario(2);
  const Scenario out = with_stable_substeps(sc, {&coarse, &fine});
  const double limit = level_estimate(fine, sc);  // the finest level sets it
  EXPECT_LT(limit, level_estimate(coarse, sc));
  EXPECT_DOUBLE_EQ(stable_step(sc, {&coarse, &fine}).dt, limit);
  // From the models a run builds once for the step and the simulation: the same estimate.
  const LevelLaws laws = level_laws(sc, {&coarse, &fine});
  const std::vector<LevelModel> models = level_models(sc, {&coarse, &fine}, laws);
  EXPECT_EQ(stable_step(sc, {&coarse, &fine}, &laws, &models).dt, limit);
  const double dt = 0.02 / out.time.substeps;
  EXPECT_LE(dt, limit);
  EXPECT_GT(0.02 / (out.time.substeps - 1), limit);  // the fewest such steps
  EXPECT_EQ(out.resolved["time"]["substeps"], out.time.substeps);  // scenario.yaml reruns it
  // Adaptivity off: only level 0 is simulated, the step follows it.
  const int coarse_steps = with_stable_substeps(beam_scenario(1), {&coarse, &fine}).time.substeps;
  const double coarse_limit = stable_step(beam_scenario(1), {&coarse, &fine}).dt;
  EXPECT_EQ(coarse_limit, level_estimate(coarse, sc));
  EXPECT_LE(0.02 / coarse_steps, coarse_limit);
  EXPECT_GT(0.02 / (coarse_steps - 1), coarse_limit);
  EXPECT_LT(coarse_steps, out.time.substeps);
  // Semi-implicit: at least twice the step (the thesis' claim); the level's filtered limit
  // 2/√λ_f over the margin (measured in tests/time/test_stability).
  Scenario si = sc;
  si.time.integrator = Integrator::SemiImplicit;
  EXPECT_LE(with_stable_substeps(si, {&coarse, &fine}).time.substeps * 2, out.time.substeps + 1);
  const LevelModel fine_model = build_level_model(fine, material_law(sc.material), true);
  const SpectralScale& f = fine_model.filter_spectrum;
  const double filtered = 2 / std::sqrt(f.scale * kSemiImplicitShare * f.star_max);
  EXPECT_NEAR(stable_step(si, {&coarse, &fine}).dt, filtered, 1e-9 * filtered);
  EXPECT_LT(filtered, 2 / std::sqrt(kSpectralMargin * f.eigenvalue));  // Green strain: more
  // Newton–Cotes (two-step midpoint): stable to 1/ω, half the kick-drift step; warned when damped.
  Scenario nc = sc;
  nc.time.integrator = Integrator::NewtonCotes;
  const int nc_steps = with_stable_substeps(nc, {&coarse, &fine}).time.substeps;
  EXPECT_GE(nc_steps, 2 * out.time.substeps - 1);
  EXPECT_LE(nc_steps, 2 * out.time.substeps);
  nc.material.psi = 1;
  ::testing::internal::CaptureStderr();
  with_stable_substeps(nc, {&coarse, &fine});
  EXPECT_NE(::testing::internal::GetCapturedStderr().find("newton_cotes with material.damping"),
            std::string::npos);
  // Given substeps are kept as they are.
  Scenario given = sc;
  given.time.substeps = 7;
  EXPECT_EQ(with_stable_substeps(given, {&coarse, &fine}).time.substeps, 7);
}

// One global step takes the fewest steps that fit, a multiple of the frame's split checks; time
// levels a power of two, four times the one that fits (two finer levels); never above the cap.
TEST(StableStep, ComputedSubstepsAreTheFewestThatFitOrAPowerOfTwoWithTimeLevels) {
  EXPECT_EQ(computed_substeps(0.02, 0.02 / 103.4, false, 1), 104);
  EXPECT_EQ(computed_substeps(0.02, 0.02 / 103, false, 1), 103);  // exactly: no extra step
  EXPECT_EQ(computed_substeps(0.02, 0.02 / 103, false, 4), 104);
  EXPECT_EQ(computed_substeps(0.02, 0.02 / 103, false, 8), 104);
  EXPECT_EQ(computed_substeps(0.02, 0.02 / 105, false, 8), 112);
  EXPECT_EQ(computed_substeps(0.02, 1.0, false, 1), 1);  // a step longer than the frame
  EXPECT_EQ(computed_substeps(0.02, 1.0, false, 4), 4);
  EXPECT_EQ(computed_substeps(0.02, 0.02 / 103.4, true, 1), 4 * 128);
  EXPECT_EQ(computed_substeps(0.02, 0.02 / 128, true, 1), 4 * 128);
  EXPECT_EQ(computed_substeps(0.02, 1e-300, false, 1), kMaxSubsteps);
  EXPECT_EQ(computed_substeps(0.02, 1e-300, false, 3) % 3, 0);
  EXPECT_LE(computed_substeps(0.02, 1e-300, false, 3), kMaxSubsteps);
  EXPECT_EQ(computed_substeps(0.02, 1e-300, true, 1), kMaxSubsteps);
  for (const double allowed : {3.3e-5, 1.7e-4, 2.0e-4, 6.1e-3}) {
    const long long n = computed_substeps(0.02, allowed, false, 1);
    EXPECT_LE(0.02 / n, allowed);
    EXPECT_GT(0.02 / (n - 1), allowed);
  }
}

// time.adapt_substeps: a frame whose step exceeds the estimate in force takes the fewest steps
// that fit it with 5 % to spare (not the doublings of before, up to twice too many), and the
// next frame keeps them while no fewer fit.
TEST(StableStep, TooLongAStepBecomesTheFewestStepsThatFitWithSomeToSpare) {
  const TetMesh mesh = mrsim::testing::beam_mesh(10);
  Scenario sc = beam_scenario(1);
  sc.time.substeps = 4;  // far longer than the cells allow
  sc.time.adapt_substeps = true;
  HierarchySetup setup = hierarchy_setup(sc, {&mesh});
  ASSERT_TRUE(setup.adapt_step);
  HierarchicalSimulation sim({&mesh}, setup);
  const double allowed = sim.stable_step_in_force().dt;
  const long long fit = fewest_steps(0.02, allowed / 1.05, 1, kMaxSubsteps);
  sim.advance_frame();
  EXPECT_EQ(sim.steps_per_frame(), fit);
  EXPECT_EQ(sim.steps(), fit);
  EXPECT_LE(0.02 / sim.steps_per_frame(), allowed / 1.05);
  EXPECT_GT(0.02 / (sim.steps_per_frame() - 1), allowed / 1.05);
  EXPECT_NE(sim.steps_per_frame() % 4, 0);  // not 4 × a power of two: 4 × 2^k overshoots
  sim.advance_frame();  // the estimate in force barely moves: the same steps
  EXPECT_EQ(sim.steps_per_frame(), fit);
  EXPECT_EQ(sim.steps(), 2 * fit);
}

TEST(StableStep, DampingShortensTheComputedStepAndIsNamedAsTheCause) {
  const TetMesh mesh = mrsim::testing::beam_mesh(10);
  Scenario sc = beam_scenario(1);
  sc.material.psi = 200;  // Pa·s: ζ of the highest mode well above 1
  const StableStep damped = stable_step(sc, {&mesh});
  EXPECT_LT(damped.dt, 0.5 * stable_step(beam_scenario(1), {&mesh}).dt);
  EXPECT_NE(damped.cause.find("damping"), std::string::npos) << damped.cause;
  EXPECT_GT(with_stable_substeps(sc, {&mesh}).time.substeps,
            with_stable_substeps(beam_scenario(1), {&mesh}).time.substeps);
}

TEST(StableStep, HeldPointsNeitherSetTheStepNorEnterTheSpectra) {
  // A clamped, heavily damped beam whose cells thin towards the clamp: the held face never
  // moves, so the estimate is that of the free points, with the level's spectra over them
  // (LevelModel::held), and the simulation the run builds from the same scenario holds the same
  // points and starts from the same estimate.
  TetMesh mesh = mrsim::testing::beam_mesh(10);
  for (Vec3& p : mesh.points) p.x() = p.x() * p.x() / mrsim::testing::kBeamL;
  Scenario sc = beam_scenario(1);
  sc.material.psi = 200;
  const StableStep loose = stable_step(sc, {&mesh});
  FixedRegion clamp;
  clamp.kind = FixedRegion::Kind::HalfSpace;
  clamp.normal = Vec3(-1, 0, 0);  // x <= 0
  sc.fixed.push_back(clamp);
  const LevelLaws laws = level_laws(sc, {&mesh});
  const LevelModel m = build_level_model(mesh, laws.laws[0], false, laws.held[0]);
  double free_min = INFINITY;
  int held = 0;
  for (int i = 0; i < m.num_points(); ++i) {
    if (is_held(m, i)) {
      ++held;
      continue;
    }
    free_min = std::min(free_min, stable_step_of(calibrated(m.star[i], m), false));
  }
  EXPECT_EQ(held, 9);  // the 3 × 3 points of the x = 0 face
  const StableStep clamped = stable_step(sc, {&mesh});
  EXPECT_EQ(clamped.dt, free_min);
  EXPECT_FALSE(is_held(m, clamped.point));
  EXPECT_GT(clamped.dt, loose.dt);
  const Scenario run = with_stable_substeps(sc, {&mesh});
  HierarchicalSimulation sim({&mesh}, hierarchy_setup(run, {&mesh}));
  EXPECT_EQ(sim.model(0).held, laws.held[0]);
  EXPECT_DOUBLE_EQ(sim.stable_step_in_force().dt, clamped.dt);
}

TEST(StableStep, AStiffToolPenaltyShortensTheComputedStepAndIsNamedAsTheCause) {
  const TetMesh mesh = mrsim::testing::beam_mesh(10);
  Scenario sc = beam_scenario(1);
  sc.resolved["time"]["duration"] = 0.1;
  sc.time.duration = 0.1;
  ToolSpec tool;
  tool.name = "probe";
  tool.shape = "sphere";
  tool.radius = 0.005;
  tool.keyframes = {{0.0, Vec3(0.09, 0.01, 0.025), {1, 0, 0, 0}},
                    {0.1, Vec3(0.09, 0.01, 0.019), {1, 0, 0, 0}}};
  tool.stiffness = 1e11;  // Pa/m: 10⁴ times `auto` on these 5 mm cells
  sc.tools.push_back(tool);
  const StableStep s = stable_step(sc, {&mesh});
  EXPECT_LT(s.dt, 0.2 * stable_step(beam_scenario(1), {&mesh}).dt);
  EXPECT_NE(s.cause.find("contact penalty"), std::string::npos) << s.cause;
  // `auto` leaves the cells in charge.
  sc.tools[0].stiffness = 0;
  EXPECT_NE(stable_step(sc, {&mesh}).cause.find("cells"), std::string::npos);
}

TEST(StableStep, AStepBeyondTheCapIsAnInputErrorNamingTheCause) {
  // A mesh of 1e-12 m cells (a unit mistake): 2^30 substeps would still be 68 times too large.
  TetMesh mesh = make_box_mesh(Vec3(0, 0, 0), Vec3(1e-11, 2e-12, 2e-12), 10, 2, 2);
  const Scenario sc = beam_scenario(1);
  try {
    with_stable_substeps(sc, {&mesh});
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("more than the 1073741824"), std::string::npos) << m;
    EXPECT_NE(m.find("level 0, point"), std::string::npos) << m;
    EXPECT_NE(m.find("set by the cells"), std::string::npos) << m;
    EXPECT_NE(m.find("object.units"), std::string::npos) << m;
  } catch (...) {
    FAIL() << "not an InputError";
  }
  // Given substeps: the run would keep doubling them (time.adapt_substeps), so the same error;
  // with the step held fixed on purpose, only the warning.
  Scenario given = sc;
  given.time.substeps = 512;
  EXPECT_THROW(with_stable_substeps(given, {&mesh}), InputError);
  given.time.adapt_substeps = false;
  EXPECT_EQ(with_stable_substeps(given, {&mesh}).time.substeps, 512);
}

TEST(StableStep, TheComputedStepRunsTheBeamWithoutGrowth) {
  // Undamped, the worst case for the explicit scheme: the energy stays bounded over 20 000
  // steps at the computed step (above the real limit it grows by orders of magnitude).
  const TetMesh mesh = mrsim::testing::beam_mesh(20);
  const Scenario out = with_stable_substeps(beam_scenario(1), {&mesh});
  LevelSimulation sim(
      mesh, mrsim::testing::beam_setup(mesh, Integrator::ModifiedEuler, 0.02 / out.time.substeps));
  double worst = 0;
  for (int k = 0; k < 20; ++k) {
    sim.advance(1000);
    for (const Vec3& u : sim.state().u) worst = std::max(worst, u.norm());
  }
  EXPECT_LT(worst, 0.02);  // twice the static tip deflection is ~6 mm
}
