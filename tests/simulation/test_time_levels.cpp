// Per-particle time levels and the W-cycle on the hierarchy (issue 5, method.md §5.2, §5.4).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

#include "beam_fixture.hpp"
#include "physics/internal_force.hpp"
#include "physics/spectral_bound.hpp"
#include "physics/tangent_growth.hpp"
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
  return make_graded_box_mesh(Vec3(0, 0, 0), Vec3(kBeamL, kBeamH, kBeamH), widths, 4, 4);
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
  r.courant = 1.0;  // the default fraction of the stable-step estimate
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
    const int level = is_semi_implicit(integ) ? 7 : 9;
    HierarchicalSimulation global({&mesh}, global_step(clamped(mesh, integ), 1 << level));
    HierarchicalSimulation adaptive({&mesh}, time_levels(clamped(mesh, integ), level));
    for (int f = 0; f < 5; ++f) {
      global.advance_frame();
      adaptive.advance_frame();
    }
    ASSERT_EQ(adaptive.time_levels()->particles_per_level().back(), 500);
    for (size_t i = 0; i < mesh.points.size(); ++i) {
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
  // Coarse cells (5 mm edges) on 9, the node planes inside the slab of 0.74 mm cells on 11;
  // its two faces carry a coarse and a thin half star: level 10 (their own stable step).
  EXPECT_EQ(levels[9], 389);
  EXPECT_EQ(levels[10], 36);
  EXPECT_EQ(levels[11], 175);
  const auto e_coarse = energies(coarse, 25), e_fine = energies(fine, 25),
             e_adaptive = energies(adaptive, 25);
  ASSERT_LT(e_coarse.size(), 25u) << "the coarse global step should have diverged";
  ASSERT_EQ(e_adaptive.size(), 25u);
  double worst = 0;
  for (size_t f = 4; f < 25; ++f)
    worst = std::max(worst, std::abs(e_adaptive[f] - e_fine[f]) / e_fine[f]);
  EXPECT_LT(worst, 1e-2);
  const double cost = static_cast<double>(adaptive.force_evaluations(0)) /
                      static_cast<double>(fine.force_evaluations(0));
  std::printf(
      "tiny-tet slab: global step at the coarse Courant limit diverged after %zu frames; "
      "time levels: energy within %.2e of the finest global step at %.3f of its force "
      "evaluations\n",
      e_coarse.size(), worst, cost);
  EXPECT_LT(cost, 0.6);
}

// Semi-implicit time levels keep the proven bounds (at the thesis' quarter share) rather than
// the level's spectral scale of the one global step: a scale uniform over a level whose point
// bounds are loose in a slab of tiny tets and tight elsewhere lets particles step beyond their
// own limit. Calibrated like the one global step, the slabs 8 and 16 times thinner diverged
// within three frames at courant 1 (2026-11-28); with the proven bounds they run.
TEST(TimeLevels, SemiImplicitTinySlabsRunAtTheirEstimates) {
  for (int ratio : {8, 16}) {
    const TetMesh mesh = graded_beam({{8, 1}, {8, ratio}, {8, 1}});
    HierarchySetup s = time_levels(clamped(mesh, Integrator::SemiImplicit), 12);
    s.time_levels->velocity_change = 1e9;  // each particle on its stable level
    HierarchicalSimulation sim({&mesh}, s);
    const std::vector<std::int64_t> n = sim.time_levels()->particles_per_level();
    EXPECT_GE(std::count_if(n.begin(), n.end(), [](std::int64_t c) { return c > 0; }), 2)
        << "the slab should step finer than the rest";
    const std::vector<double> e = energies(sim, 25);
    ASSERT_EQ(e.size(), 25u) << "slab " << ratio << " diverged";
    EXPECT_LT(e.back(), 1e-4) << "slab " << ratio;
  }
}

// Issue 5 point 4: the W-cycle spreads the work. A beam with three time levels (cells of w,
// w / 2 and w / 8): no sub-step kicks two coarser levels together (aligned at the ends of their
// steps, every level would be kicked at once at the last sub-step of each coarse step), so the
// busiest sub-step stays near twice the mean.
TEST(TimeLevels, ScheduleKicksAtMostTwoLevelsPerSubStep) {
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
  std::printf(
      "W-cycle, particles on levels 9/10/11: %lld/%lld/%lld; %zu sub-steps, work per "
      "sub-step max %.0f mean %.1f (max/mean %.2f)\n",
      static_cast<long long>(n[9]), static_cast<long long>(n[10]), static_cast<long long>(n[11]),
      work.size(), max, mean, max / mean);
  // At most two levels per sub-step: the finest and one coarser (aligned ends would kick all
  // three at the last sub-step). With 577/48/175 particles the coarse level 9 dominates: its
  // tick carries 752 of a mean 343 (2.19).
  EXPECT_LE(max, n[11] + std::max(n[9], n[10]));
  EXPECT_LT(max, n[9] + n[10] + n[11]);
  EXPECT_LE(max / mean, 2.25);
}

}  // namespace
}  // namespace mrsim

namespace mrsim {
namespace {

// Issue 5 point 4: on the validation beam (20x4x4, undamped, sudden gravity) the time levels
// leave every particle on its Courant level (4 times the finest step) unless its velocity
// changes fast; the tip's mean deflection and first frequency stay within 1 % of the run with
// the finest step everywhere.
TEST(TimeLevels, BeamTipAndFrequencyWithinOnePercentOfTheFinestStep) {
  const TetMesh mesh = testing::beam_mesh(20);
  const double frame = 0.002;  // 43 samples per period of the 11.6 Hz mode
  HierarchySetup base = clamped(mesh, Integrator::ModifiedEuler);
  base.law.psi = 0;
  HierarchySetup global = global_step(base, 128);
  global.dt = frame / 128;
  HierarchySetup adaptive = time_levels(base, 7);
  adaptive.time_levels->frame_dt = frame;
  HierarchicalSimulation a({&mesh}, global), b({&mesh}, adaptive);
  EXPECT_EQ(b.time_levels()->particles_per_level()[5], 500);  // Courant level: 6.25e-5 s
  std::vector<double> wa, wb;
  auto tip = [&](const HierarchicalSimulation& sim) {
    double sum = 0;
    int n = 0;
    for (size_t i = 0; i < mesh.points.size(); ++i)
      if (mesh.points[i].x() > kBeamL - 1e-12) {
        sum -= sim.state(0).u[i].z();
        ++n;
      }
    return sum / n;
  };
  for (int f = 0; f < 600; ++f) {
    a.advance_frame();
    b.advance_frame();
    wa.push_back(tip(a));
    wb.push_back(tip(b));
  }
  const testing::Oscillation oa = testing::measure_oscillation(wa, frame),
                             ob = testing::measure_oscillation(wb, frame);
  const double cost = static_cast<double>(b.force_evaluations(0)) / a.force_evaluations(0);
  std::printf(
      "beam 20x4x4: finest step %.4e m %.4f Hz; time levels %.4e m %.4f Hz (%.3f %%, "
      "%.3f %%) at %.3f of the force evaluations\n",
      oa.mean, oa.frequency, ob.mean, ob.frequency, 100 * (ob.mean / oa.mean - 1),
      100 * (ob.frequency / oa.frequency - 1), cost);
  ASSERT_GE(oa.periods, 10);
  EXPECT_NEAR(ob.mean, oa.mean, 0.01 * oa.mean);
  EXPECT_NEAR(ob.frequency, oa.frequency, 0.01 * oa.frequency);
  EXPECT_LT(cost, 0.3);
}

// The velocity-change rule (method.md §5.2): with a small beta, the sudden load sends particles
// to finer levels during the first frame, where they are kicked at once (level 12 had nobody at
// the start); they come back at frame boundaries, never below their Courant level.
TEST(TimeLevels, VelocityChangeRefinesAtOnceAndCoarsensAtFrameBoundaries) {
  const TetMesh mesh = tiny_slab_beam();
  HierarchicalSimulation sim({&mesh},
                             time_levels(clamped(mesh, Integrator::ModifiedEuler), 13, 1e-6));
  const TimeAdaptivity& ta = *sim.time_levels();
  ASSERT_EQ(ta.particles_per_level()[12], 0);
  std::vector<TimeLevelChange> changes;
  sim.advance_frame(&changes);
  const auto refined = std::count_if(changes.begin(), changes.end(),
                                     [](const TimeLevelChange& c) { return c.to > c.from; });
  EXPECT_GT(refined, 100);
  EXPECT_GT(ta.evaluations()[12], 0);  // kicked on level 12 within the frame of the refinement
  int coarsenings = 0, finest = 0;
  for (int f = 1; f < 50; ++f) {
    changes.clear();
    sim.advance_frame(&changes);
    for (const TimeLevelChange& c : changes) {
      ASSERT_EQ(std::abs(c.to - c.from), 1);
      coarsenings += c.to < c.from;
      finest = std::max(finest, c.to);
    }
    const auto n = ta.particles_per_level();
    ASSERT_EQ(std::accumulate(n.begin(), n.begin() + 9, std::int64_t{0}), 0) << "below Courant";
    ASSERT_EQ(std::accumulate(n.begin(), n.end(), std::int64_t{0}), 600);
  }
  std::printf(
      "velocity rule (beta 1e-6): %lld refinements in the first frame, %d coarsenings "
      "over 1 s, finest level %d\n",
      static_cast<long long>(refined), coarsenings, finest);
  EXPECT_GT(coarsenings, 100);
  EXPECT_LE(finest, 13);
}

// Issue 5 point 3: every integrator runs with time levels on the tiny-slab beam. The explicit
// ones follow their global finest step; the semi-implicit ones run on levels twice as coarse
// (the Courant bound doubled, §5.3), where the explicit step explodes, and damp more than on the
// finest step (the filter's damping grows with dt).
TEST(TimeLevels, EveryIntegratorWorksWithTimeLevels) {
  const TetMesh mesh = tiny_slab_beam();
  for (Integrator integ : {Integrator::ModifiedEuler, Integrator::StoermerVerlet,
                           Integrator::SemiImplicit, Integrator::SemiImplicitMomentum}) {
    const bool semi = is_semi_implicit(integ);
    const int fine = semi ? 10 : 11;
    HierarchicalSimulation g({&mesh}, global_step(clamped(mesh, integ), 1 << 11));
    HierarchicalSimulation a({&mesh}, time_levels(clamped(mesh, integ), fine));
    const auto eg = energies(g, 15), ea = energies(a, 15);
    ASSERT_EQ(ea.size(), 15u) << integrator_name(integ);
    const double gap = (ea.back() - eg.back()) / eg.back();
    std::printf(
        "%s, levels %d and %d: energy after 0.3 s %.4e J (finest global step: %.4e J, "
        "%+.2f %%)\n",
        integrator_name(integ), fine - 2, fine, ea.back(), eg.back(), 100 * gap);
    if (semi) {
      EXPECT_LT(gap, 0) << integrator_name(integ);
      EXPECT_GT(ea.back(), 1e-3 * eg.back()) << integrator_name(integ);
    } else {
      EXPECT_LT(std::abs(gap), 0.01) << integrator_name(integ);
    }
  }
  // The same levels 8 and 10 with an explicit step: the tiny slab is past its Courant bound.
  HierarchicalSimulation me({&mesh}, time_levels(clamped(mesh, Integrator::ModifiedEuler), 10));
  EXPECT_LT(energies(me, 15).size(), 15u);
}

// A free body spinning and drifting, semi_implicit_momentum with time levels: the filter sees
// only velocities relative to the body's rigid motion and what it takes is given back over the
// whole body, so linear and angular momentum stay put although the kicked particles change
// from sub-step to sub-step (given back to the kicked particles alone, 97 % of the momentum
// leaked out in 0.5 s through the lag it left between levels). What remains is the asynchrony
// of the kicks of neighbours on different levels (modified Euler: 5e-7 of L).
TEST(TimeLevels, FreeBodyKeepsItsMomentumUnderTheMomentumRestoringSemiImplicitStep) {
  const TetMesh mesh = tiny_slab_beam();
  HierarchySetup s = clamped(mesh, Integrator::SemiImplicitMomentum);
  s.law.strain = StrainMeasure::GreenLagrange;  // rotation-invariant: a spin is no strain
  s.fixed.clear();
  s.gravity.setZero();
  s.initial_velocity = Vec3(0.3, -0.2, 0.1);
  s.initial_angular_velocity = Vec3(0, 0, 2.0);
  // At half the estimate: the particles on levels 8 and 10, where the kicks' asynchrony leaves
  // 1.6e-5 of L (at the estimate, levels 7 and 9 since the shares of physics/patch_spectrum.hpp,
  // 6e-5).
  HierarchySetup levels = time_levels(s, 10);
  levels.time_levels->courant = 0.5;
  HierarchicalSimulation sim({&mesh}, levels);
  ASSERT_GT(sim.time_levels()->particles_per_level()[8], 0);
  ASSERT_GT(sim.time_levels()->particles_per_level()[10], 0);
  auto momenta = [&] {
    std::pair<Vec3, Vec3> pl(Vec3::Zero(), Vec3::Zero());
    for (int i = 0; i < sim.model(0).num_points(); ++i) {
      const Vec3 mv = sim.model(0).mass[i] * sim.state(0).v[i];
      pl.first += mv;
      pl.second += (mesh.points[i] + sim.state(0).u[i]).cross(mv);
    }
    return pl;
  };
  const auto [p0, l0] = momenta();
  for (int f = 0; f < 25; ++f) sim.advance_frame();
  const auto [p1, l1] = momenta();
  const double dp = (p1 - p0).norm() / p0.norm(), dl = (l1 - l0).norm() / l0.norm();
  std::printf(
      "free body, time levels 8 and 10, semi_implicit_momentum: linear momentum drift "
      "%.1e, angular %.1e after 0.5 s\n",
      dp, dl);
  EXPECT_LT(dp, 5e-6);
  EXPECT_LT(dl, 2e-5);
}

// Each point's tangent growth g and damping growth g_d: the largest among its tets, each tet's
// from the single-tet functions (the reference the simulation's per-point pass is held to).
struct PointGrowths {
  std::vector<double> g, g_d;
};

PointGrowths point_growths(const LevelModel& m, const std::vector<Vec3>& u,
                           const MaterialLaw& law) {
  PointGrowths out{std::vector<double>(m.num_points(), 0.0),
                   std::vector<double>(m.num_points(), 0.0)};
  for (int t = 0; t < m.num_tets(); ++t) {
    const std::array<int, 1> one{t};
    const double g = largest_tangent_growth(m.geo, one, u, law);
    const double d = damping_growth(tet_gradient(m.geo.grad[t], m.geo.tets[t], u.data()));
    for (int a : m.geo.tets[t]) {
      out.g[a] = std::max(out.g[a], g);
      out.g_d[a] = std::max(out.g_d[a], d);
    }
  }
  return out;
}

// Semi-implicit with time levels, a Green–Lagrange level: the filter's blocks are taken at
// rest, so each frame start scales each point's proven stiffness bound by
// time_level_stiffening(g) of its own tangent growth now, the largest among its tets (without
// it two whole runs held at exactly courant × 1.00, docs/stability_matrix.md). Undamped and one
// level, every particle's step then shrinks by 1/√factor, the points near the clamp (which bend
// most) more than the free end's; the explicit steps follow only what the spectral margin does
// not cover, explicit_stiffening(g) (1 below g = 0.5). Breaking it: the level's largest g for
// every point fails the free end's points.
TEST(TimeLevels, SemiImplicitStepsFollowGreenLagrangeStiffening) {
  const TetMesh mesh = graded_beam({{16, 1}});
  std::vector<int> all(mesh.tets.size());
  std::iota(all.begin(), all.end(), 0);
  for (Integrator integ : {Integrator::SemiImplicit, Integrator::ModifiedEuler}) {
    HierarchySetup s = clamped(mesh, integ);
    s.law.strain = StrainMeasure::GreenLagrange;
    s.law.psi = 0;
    s.gravity *= 200.0;  // a deep bend: g of order one
    HierarchicalSimulation sim({&mesh}, time_levels(s, 12));
    const std::vector<double> rest = sim.stable_steps(0);
    for (int f = 0; f < 5; ++f) sim.advance_frame();
    const LevelModel& m = sim.model(0);
    const double g = largest_tangent_growth(m.geo, all, sim.state(0).u, s.law);
    const std::vector<double> g_p = point_growths(m, sim.state(0).u, s.law).g;
    sim.advance_frame();  // its start reads the steps at this state
    ASSERT_GT(g, 0.1);
    int checked = 0, below_top = 0;
    for (int p = 0; p < m.num_points(); ++p) {
      if (!sim.state(0).free_point[p]) continue;
      const double share = m.time_level_share.empty() ? 0.0 : m.time_level_share[p];
      const double expected =
          1 / std::sqrt(is_semi_implicit(integ) ? time_level_stiffening(g_p[p], share) /
                                                      time_level_stiffening(0.0, share)
                                                : explicit_stiffening(g_p[p]));
      EXPECT_NEAR(sim.stable_steps(0)[p] / rest[p], expected, 1e-9) << p;
      below_top += g_p[p] < 0.5 * g;
      ++checked;
    }
    EXPECT_GT(checked, 100);
    EXPECT_GT(below_top, checked / 4);  // the points' own growths differ from the level's
  }
}

// The strain-rate damping grows with the strain too (physics/tangent_growth.hpp): semi-implicit,
// with one global step or with time levels, each frame start scales every point's damping
// bound by 1 + g_d of its own most stretched tet (and its stiffness allowance by its own g).
// Where ψ is large that is what the filter leaves explicit: without it the 125k-tet liver
// hierarchy ran 6 % beyond its true limit (docs/stability_matrix.md).
TEST(TimeLevels, SemiImplicitDampingFollowsTheStrainAtEachPoint) {
  const TetMesh mesh = graded_beam({{16, 1}});
  for (bool levels : {false, true}) {
    HierarchySetup s = clamped(mesh, Integrator::SemiImplicit);
    s.law.strain = StrainMeasure::GreenLagrange;
    s.law.psi = 20;
    s.gravity *= 200.0;
    HierarchicalSimulation sim({&mesh}, levels ? time_levels(s, 12) : global_step(s, 256));
    for (int f = 0; f < 5; ++f) sim.advance_frame();
    const LevelModel& m = sim.model(0);
    const std::vector<Vec3> u = sim.state(0).u;
    const auto [g_p, g_d] = point_growths(m, u, s.law);
    sim.advance_frame();  // its start reads the steps at this state
    int shorter = 0, checked = 0;
    for (int p = 0; p < m.num_points(); ++p) {
      if (!sim.state(0).free_point[p]) continue;
      const PointInertia& in = sim.inertia(0)[p];
      const double with =
          stable_step_of(calibrated(in, m, true, levels, g_p[p], g_d[p], p), true);
      const double without =
          stable_step_of(calibrated(in, m, true, levels, g_p[p], 0.0, p), true);
      EXPECT_NEAR(sim.stable_steps(0)[p], with, 1e-12 * with) << p;
      if (with < 0.99 * without) ++shorter;
      ++checked;
    }
    EXPECT_GT(checked, 100);
    EXPECT_GT(shorter, checked / 4) << "time levels " << levels;
  }
}

}  // namespace
}  // namespace mrsim
