// Per-particle time levels and the W-cycle on the hierarchy (issue 5, method.md §5.2, §5.4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

#include "beam_fixture.hpp"
#include "physics/internal_force.hpp"
#include "simulation/hierarchical_simulation.hpp"

namespace mrsim {
namespace {

using testing::kBeamH;
using testing::kBeamL;

// The validation beam's box (4 x 4 cells across) with cells along x in runs of {count, ratio}:
// `count` cells of width w / ratio, w set by the total length.
TetMesh graded_beam(const std::vector<std::pair<int, int>>& runs) {
  std::vector<double> widths;
  for (auto [count, ratio] : runs) widths.insert(widths.end(), count, 1.0 / ratio);
  const int nx = static_cast<int>(widths.size());
  const double w = kBeamL / std::accumulate(widths.begin(), widths.end(), 0.0);
  TetMesh m = make_box_mesh(Vec3(0, 0, 0), Vec3(1, kBeamH, kBeamH), nx, 4, 4);
  std::vector<double> x(nx + 1, 0.0);
  for (int i = 0; i < nx; ++i) x[i + 1] = x[i] + w * widths[i];
  for (Vec3& p : m.points) p.x() = x[static_cast<size_t>(std::lround(p.x() * nx))];
  return m;
}

// One slab of 8 cells 8 times thinner across the middle of the beam.
TetMesh tiny_slab_beam() { return graded_beam({{8, 1}, {8, 8}, {8, 1}}); }

constexpr double kFrame = 0.02;

// Clamped at x = 0 under gravity, light strain-rate damping.
HierarchySetup clamped(const TetMesh& mesh, Integrator integ) {
  const LevelSetup beam = testing::beam_setup(mesh, integ, 0);
  HierarchySetup s;
  s.law = beam.law;
  s.law.psi = 0.5;
  s.gravity = beam.gravity;
  s.integrator = integ;
  s.fixed = {beam.fixed};
  return s;
}

HierarchySetup global_step(HierarchySetup s, int substeps) {
  s.dt = kFrame / substeps;
  s.steps_per_frame = substeps;
  return s;
}

HierarchySetup time_levels(HierarchySetup s, int max_level, double beta = 0.01) {
  TimeLevelRules r;
  r.frame_dt = kFrame;
  r.max_level = max_level;
  r.courant = 0.5;
  r.velocity_change = beta;
  r.semi_implicit = is_semi_implicit(s.integrator);
  s.time_levels = r;
  return s;
}

double total_energy(const HierarchicalSimulation& sim) {
  double e = elastic_energy(sim.model(0), sim.state(0).u.data());
  for (int i = 0; i < sim.model(0).num_points(); ++i)
    e += 0.5 * sim.model(0).mass[i] * sim.state(0).v[i].squaredNorm();
  return e;
}

// Energy after each of `frames` frames (stops early once it is not finite or above 1 J).
std::vector<double> energies(HierarchicalSimulation& sim, int frames) {
  std::vector<double> e;
  for (int f = 0; f < frames; ++f) {
    sim.advance_frame();
    e.push_back(total_energy(sim));
    if (!std::isfinite(e.back()) || e.back() > 1) break;
  }
  return e;
}

// Uniform mesh, every particle on the one time level the cap allows: the W-cycle kicks all at
// every tick and drifts them in between, which is exactly the global step, bit for bit.
TEST(TimeLevels, OneLevelIsExactlyTheGlobalStep) {
  const TetMesh mesh = testing::beam_mesh(20);  // Courant level 9 at 0.02 s frames
  for (Integrator integ : {Integrator::ModifiedEuler, Integrator::SemiImplicit}) {
    const int level = is_semi_implicit(integ) ? 8 : 9;
    HierarchicalSimulation global({&mesh}, global_step(clamped(mesh, integ), 1 << level));
    HierarchicalSimulation adaptive({&mesh}, time_levels(clamped(mesh, integ), level));
    for (int f = 0; f < 5; ++f) {
      global.advance_frame();
      adaptive.advance_frame();
    }
    ASSERT_EQ(adaptive.time_levels()->particles_per_level().back(), 500);
    for (int i = 0; i < mesh.points.size(); ++i) {
      ASSERT_EQ(global.state(0).u[i], adaptive.state(0).u[i]) << integrator_name(integ) << " " << i;
      ASSERT_EQ(global.state(0).v[i], adaptive.state(0).v[i]) << integrator_name(integ) << " " << i;
    }
    EXPECT_NEAR(global.time(), adaptive.time(), 1e-12);
  }
}

// Issue 5 point 4: one slab of tiny tets (8 times thinner) across the beam. One global step at
// the coarse particles' Courant limit explodes; with time levels the tiny region steps 4 times
// finer than the rest, stays stable, follows the global finest step and costs about half of it.
TEST(TimeLevels, TinyTetRegionIsStableWhereTheCoarseGlobalStepExplodes) {
  const TetMesh mesh = tiny_slab_beam();
  const auto integ = Integrator::ModifiedEuler;
  HierarchicalSimulation coarse({&mesh}, global_step(clamped(mesh, integ), 512));
  HierarchicalSimulation fine({&mesh}, global_step(clamped(mesh, integ), 2048));
  HierarchicalSimulation adaptive({&mesh}, time_levels(clamped(mesh, integ), 11));
  const std::vector<std::int64_t> levels = adaptive.time_levels()->particles_per_level();
  EXPECT_EQ(levels[9], 375);   // coarse cells: 5 mm edges
  EXPECT_EQ(levels[11], 225);  // the 9 node planes that touch the 0.74 mm cells
  const auto e_coarse = energies(coarse, 25), e_fine = energies(fine, 25),
             e_adaptive = energies(adaptive, 25);
  ASSERT_LT(e_coarse.size(), 25u) << "the coarse global step should have diverged";
  ASSERT_EQ(e_adaptive.size(), 25u);
  double worst = 0;
  for (size_t f = 4; f < 25; ++f)
    worst = std::max(worst, std::abs(e_adaptive[f] - e_fine[f]) / e_fine[f]);
  EXPECT_LT(worst, 2e-3);
  const double cost = static_cast<double>(adaptive.force_evaluations(0)) /
                      static_cast<double>(fine.force_evaluations(0));
  std::printf("tiny-tet slab: global step at the coarse Courant limit diverged after %zu frames; "
              "time levels: energy within %.2e of the finest global step at %.3f of its force "
              "evaluations\n", e_coarse.size(), worst, cost);
  EXPECT_LT(cost, 0.6);
}

// Issue 5 point 4: the W-cycle spreads the work. A beam with three time levels (cells of w,
// w / 2 and w / 8): per sub-step, the particles kicked stay within twice their mean over the
// frame, and no sub-step kicks two coarser levels together (aligned at the ends of their
// steps, every level would be kicked at once at the last sub-step of each coarse step).
TEST(TimeLevels, ScheduleWorkPerSubStepStaysWithinTwiceTheMean) {
  const TetMesh mesh = graded_beam({{6, 1}, {6, 2}, {6, 1}, {8, 8}, {6, 1}});
  HierarchicalSimulation sim({&mesh}, time_levels(clamped(mesh, Integrator::ModifiedEuler), 11));
  const std::vector<std::int64_t> n = sim.time_levels()->particles_per_level();
  ASSERT_GT(n[9], 0);
  ASSERT_GT(n[10], 0);
  ASSERT_GT(n[11], 0);
  sim.advance_frame();
  const auto& work = sim.time_levels()->frame_work();
  ASSERT_FALSE(work.empty());
  const double mean = std::accumulate(work.begin(), work.end(), 0.0) / work.size();
  const double max = static_cast<double>(*std::max_element(work.begin(), work.end()));
  std::printf("W-cycle, particles on levels 9/10/11: %lld/%lld/%lld; %zu sub-steps, work per "
              "sub-step max %.0f mean %.1f (max/mean %.2f)\n", static_cast<long long>(n[9]),
              static_cast<long long>(n[10]), static_cast<long long>(n[11]), work.size(), max,
              mean, max / mean);
  EXPECT_LE(max / mean, 2.0);
  EXPECT_LE(max, n[11] + std::max(n[9], n[10]));
}

}  // namespace
}  // namespace mrsim
