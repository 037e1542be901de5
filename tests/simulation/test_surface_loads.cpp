// Surface loads (scenario `loads`): nodal forces that sum to the load on every level, a time
// profile, and the acceptance test of issue 4 point 6 — a block pressed locally refines under
// the load, matches the uniform finest mesh there at a fraction of its cost, and coarsens back
// when released.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdio>

#include "core/error.hpp"
#include "hierarchy/hierarchy_fixture.hpp"
#include "simulation/hierarchy_diagnostics.hpp"
#include "simulation/space_adaptivity.hpp"
#include "simulation/surface_load_distribution.hpp"

using namespace mrsim;

namespace {

// The 0.1 x 0.06 x 0.04 m block, pressed on a 2 x 2 cm patch in the middle of its top face.
SurfaceLoadSpec top_patch(double newtons) {
  SurfaceLoadSpec s;
  s.min = Vec3(0.04, 0.02, 0.04 - 1e-6);
  s.max = Vec3(0.06, 0.04, 0.04 + 1e-6);
  s.force = Vec3(0, 0, -newtons);
  return s;
}

std::vector<const TetMesh*> ptrs(const std::vector<TetMesh>& m) {
  std::vector<const TetMesh*> p;
  for (const auto& x : m) p.push_back(&x);
  return p;
}

}  // namespace

TEST(SurfaceLoads, TheFinestSkinCarriesTheWholeForceOnItsTopFaces) {
  const auto meshes = mrsim::testing::jittered_box_levels({{16, 10, 7}}, 8, 0.15);
  const SurfaceLoad load = distribute_surface_load(meshes[0], top_patch(2.0), 0);
  Vec3 sum = Vec3::Zero();
  for (size_t k = 0; k < load.finest.points.size(); ++k) {
    sum += load.finest.force[k];
    EXPECT_NEAR(meshes[0].points[load.finest.points[k]].z(), 0.04, 1e-12);  // top face only
  }
  EXPECT_LT((sum - Vec3(0, 0, -2.0)).norm(), 1e-12);
  // 6.25 x 6 mm cells over a 2 x 2 cm patch: a 4 x 4 block of faces' vertices, at least.
  EXPECT_GE(load.finest.points.size(), 16u);
}

TEST(SurfaceLoads, ABoxOffTheBodyIsAnInputError) {
  const auto meshes = mrsim::testing::jittered_box_levels({{4, 3, 2}}, 8, 0.15);
  SurfaceLoadSpec s = top_patch(1.0);
  s.min.z() = s.max.z() = 0.5;
  EXPECT_THROW(distribute_surface_load(meshes[0], s, 3), InputError);
}

TEST(SurfaceLoads, ProfileIsPiecewiseLinearAndHeldBeyondItsEnds) {
  const std::vector<std::pair<double, double>> p{{0.1, 0.0}, {0.3, 1.0}, {0.5, 1.0}, {0.6, 0.0}};
  EXPECT_DOUBLE_EQ(load_factor(p, 0.0), 0.0);
  EXPECT_NEAR(load_factor(p, 0.2), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(load_factor(p, 0.4), 1.0);
  EXPECT_NEAR(load_factor(p, 0.55), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(load_factor(p, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(load_factor({}, 1.0), 1.0);
}

// What the refinement ahead of loads reads: the largest magnitude over a window, found at the
// window's ends or at a knot inside it (a pulse shorter than the window is not missed).
TEST(SurfaceLoads, PeakOverAWindowIsAtAnEndOrAKnotWithin) {
  const std::vector<std::pair<double, double>> p{{0.1, 0.0}, {0.3, 1.0}, {0.5, 1.0}, {0.6, 0.0}};
  EXPECT_DOUBLE_EQ(peak_load_factor(p, 0.0, 0.1), 0.0);  // before the ramp
  EXPECT_NEAR(peak_load_factor(p, 0.0, 0.2), 0.5, 1e-12);  // ramping in: the window's end
  EXPECT_DOUBLE_EQ(peak_load_factor(p, 0.25, 0.55), 1.0);  // the knots inside
  EXPECT_NEAR(peak_load_factor(p, 0.55, 0.7), 0.5, 1e-12);  // ramping out: its start
  const std::vector<std::pair<double, double>> pulse{{0.0, 0.0}, {0.11, -2.0}, {0.12, 0.0}};
  EXPECT_DOUBLE_EQ(peak_load_factor(pulse, 0.1, 0.2), -2.0);  // within, and its sign
  EXPECT_DOUBLE_EQ(peak_load_factor(pulse, 0.2, 0.3), 0.0);
  EXPECT_DOUBLE_EQ(peak_load_factor({}, 0.0, 1.0), 1.0);
}

namespace {

struct PressResult {
  double patch_uz = 0;        // mean vertical displacement of the finest level's patch points, m
  Vec3 reaction = Vec3::Zero();
  std::int64_t work = 0;      // force evaluations, all levels
  std::size_t fine_active = 0;
  std::vector<std::size_t> fine_active_per_frame;
};

// Clamped at z = 0, the load ramped over 0.1 s then held (and released at `release` if > 0),
// frames of 0.01 s, heavily damped so that it settles.
PressResult press(const std::vector<TetMesh>& meshes, bool adaptive, double release,
                  Coupling coupling = Coupling::Energy) {
  HierarchySetup hs;
  hs.coupling = coupling;
  hs.law.strain = StrainMeasure::GreenLagrange;
  hs.law.lambda = 5.0e4;
  hs.law.mu = 2.0e4;
  hs.law.psi = 20;
  hs.law.density = 1000;
  hs.dt = 5e-5;
  hs.fixed = mrsim::testing::fixed_where(meshes, [](const Vec3& X) { return X.z() < 1e-9; });
  SurfaceLoadSpec spec = top_patch(1.0);
  spec.profile = {{0.0, 0.0}, {0.1, 1.0}};
  if (release > 0) spec.profile.insert(spec.profile.end(), {{release, 1.0}, {release + 0.05, 0.0}});
  hs.loads.push_back(distribute_surface_load(meshes.back(), spec, 0));
  HierarchicalSimulation sim(ptrs(meshes), hs);
  SpaceAdaptivitySettings s;
  s.enabled = adaptive;
  s.refine_above = 6e-3;  // 1e-2: 16 % at 12 % of the cost; 5e-3: 0.7 % at 44 % (measured)
  s.coarsen_below = 1.5e-3;
  s.min_dwell_frames = 3;
  SpaceAdaptivity adapt(s, sim);
  std::vector<HierarchyEvent> events;
  const int frames = release > 0 ? 60 : 25;
  PressResult r;
  const int fine = static_cast<int>(meshes.size()) - 1;
  for (int frame = 0; frame < frames; ++frame) {
    adapt.update(sim, frame, events);
    sim.advance(200);
    r.fine_active_per_frame.push_back(sim.lists().active(fine).size());
  }
  EXPECT_TRUE(sim.hierarchy().check_invariants().empty());
  sim.compute_forces();
  r.reaction = support_reaction(sim);
  sim.fill_inactive();
  const NodalLoad& patch = hs.loads[0].finest;
  for (int p : patch.points) r.patch_uz += sim.state(fine).u[p].z() / patch.points.size();
  for (int l = 0; l <= fine; ++l) r.work += sim.force_evaluations(l);
  r.fine_active = sim.lists().active(fine).size();
  return r;
}

}  // namespace

TEST(SurfaceLoads, LocalPressAdaptiveMatchesTheUniformFinestMeshAtAFractionOfItsCost) {
  const auto meshes = mrsim::testing::jittered_box_levels({{4, 3, 2}, {8, 5, 4}, {16, 10, 7}}, 8, 0.15);
  const PressResult uniform = press({meshes[2]}, false, 0);
  const PressResult adaptive = press(meshes, true, 0);
  const double err = std::abs(adaptive.patch_uz - uniform.patch_uz) / std::abs(uniform.patch_uz);
  const double cost = static_cast<double>(adaptive.work) / static_cast<double>(uniform.work);
  std::printf("patch uz: uniform finest %.4e m, adaptive %.4e m (%.2f %%); reaction z %.4f / %.4f N; "
              "cost ratio %.3f; finest active %zu of %zu\n",
              uniform.patch_uz, adaptive.patch_uz, 100 * err, uniform.reaction.z(),
              adaptive.reaction.z(), cost, adaptive.fine_active, meshes[2].points.size());
  EXPECT_LT(err, 0.05);
  EXPECT_NEAR(adaptive.reaction.z(), 1.0, 0.05);  // the supports hold the 1 N load
  EXPECT_NEAR(uniform.reaction.z(), 1.0, 0.05);
  EXPECT_LT(cost, 0.5);
  EXPECT_GT(adaptive.fine_active, 10u);
  EXPECT_LT(adaptive.fine_active, meshes[2].points.size() / 2);
  // The patch-test-consistent coupling: same answer, same kind of saving.
  const PressResult consistent = press(meshes, true, 0, Coupling::EnergyConsistent);
  const double err_c = std::abs(consistent.patch_uz - uniform.patch_uz) / std::abs(uniform.patch_uz);
  const double cost_c = static_cast<double>(consistent.work) / static_cast<double>(uniform.work);
  std::printf("energy_consistent: patch uz %.4e m (%.2f %%), reaction z %.4f N, cost ratio %.3f, "
              "finest active %zu\n", consistent.patch_uz, 100 * err_c, consistent.reaction.z(),
              cost_c, consistent.fine_active);
  EXPECT_LT(err_c, 0.05);
  EXPECT_NEAR(consistent.reaction.z(), 1.0, 0.05);
  EXPECT_LT(cost_c, 0.5);
}

TEST(SurfaceLoads, ABlockPressedLocallyRefinesThereAndCoarsensBackWhenReleased) {
  const auto meshes = mrsim::testing::jittered_box_levels({{4, 3, 2}, {8, 5, 4}, {16, 10, 7}}, 8, 0.15);
  const PressResult r = press(meshes, true, 0.2);  // load held from 0.1 s, off at 0.25 s
  const auto& fine = r.fine_active_per_frame;
  const std::size_t peak = *std::max_element(fine.begin(), fine.end());
  EXPECT_GT(peak, 100u);                   // pressed: the finest level takes over under the load
  EXPECT_LT(peak, meshes[2].points.size());
  EXPECT_EQ(fine.back(), 0u);              // released and at rest: back to the coarse levels
  EXPECT_LT(r.reaction.norm(), 1e-3);
}
