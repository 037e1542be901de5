// Rigid tools pushing the skin (issue 6, method.md §6.2): action-reaction and virtual work
// through the skin map, refinement under a sliding tool and the force signal across level
// changes. Hertz and Boussinesq are in tests/validation/test_indentation.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "contact_fixture.hpp"
#include "simulation/hierarchy_diagnostics.hpp"
#include "simulation/space_adaptivity.hpp"
#include "simulation/stable_step.hpp"

namespace mrsim {
namespace {

using testing::IndentedBlock;
using testing::courant_dt;
using testing::vertical_tool;

// Three independent box meshes (4, 2.2, 1.2 mm cells) of a 20 x 20 x 10 mm block; a sphere
// slides across at 1 mm depth so that regions under it split ahead and merge behind it.
struct SlidingProbe {
  std::vector<TetMesh> meshes;
  HierarchySetup setup;
  double frame = 0.02;
  int steps_per_frame = 0;

  // Odd cell counts: the levels share only the box's corners. Even ones (4, 8, 16) nest them:
  // every grid point of a level is a point of the next (docs/hierarchy.md, interface mass).
  explicit SlidingProbe(Coupling coupling, std::array<int, 3> cells = {5, 9, 17}) {
    for (int n : cells)
      meshes.push_back(
          make_box_mesh(Vec3(-0.01, -0.01, -0.01), Vec3(0.01, 0.01, 0), n, n, (n + 1) / 2));
    IndentedBlock material;
    const double R = 4e-3, depth = 1e-3;
    Tool tool;
    tool.name = "probe";
    tool.shape = {ToolShapeKind::Sphere, R, 0};
    tool.trajectory = ToolTrajectory({{0.0, Vec3(-0.006, 0, R + 5e-4)},
                                      {0.1, Vec3(-0.006, 0, R - depth)},
                                      {0.6, Vec3(0.006, 0, R - depth)}},
                                     Interpolation::Smooth, "probe");
    setup = material.setup(meshes[0], tool);
    setup.coupling = coupling;
    setup.fixed.clear();
    for (const TetMesh& m : meshes) {
      std::vector<std::uint8_t> fixed(m.points.size(), 0);
      for (size_t p = 0; p < m.points.size(); ++p) fixed[p] = m.points[p].z() < -0.01 + 1e-9;
      setup.fixed.push_back(fixed);
    }
    const double dt = courant_dt(meshes.back(), setup.law);
    steps_per_frame = static_cast<int>(std::ceil(frame / dt));
    setup.dt = frame / steps_per_frame;
    setup.steps_per_frame = steps_per_frame;
  }

  std::vector<const TetMesh*> pointers() const {
    std::vector<const TetMesh*> p;
    for (const TetMesh& m : meshes) p.push_back(&m);
    return p;
  }

  SpaceAdaptivitySettings adaptivity() const {
    SpaceAdaptivitySettings s;
    s.enabled = true;
    s.refine_above = 1.0;  // only contact refines: the level under the tool follows it
    s.coarsen_below = 0.5;
    s.min_dwell_frames = 2;
    s.contact_lookahead = 3 * frame;
    return s;
  }
};

// Every step: the force on the tool is minus the force handed to the body (active points plus
// the support's share). The level under the probe is the finest one whenever it touches.
// The force signal across the frames where points split and merge under the moving probe has
// no jump larger than a stated fraction of the force.
TEST(ToolContact, SlidingProbeActionReactionRefinementAndNoForceSpikes) {
  SlidingProbe probe(Coupling::Energy);
  HierarchicalSimulation sim(probe.pointers(), probe.setup);
  SpaceAdaptivity adapt(probe.adaptivity(), sim);
  std::vector<HierarchyEvent> events;
  std::vector<double> fz;
  std::vector<int> changed;  // sample index after which the topology changed
  double worst_balance = 0, scale = 0, deepest = 0;
  int touching_on_coarse = 0, touching = 0;
  for (int frame = 1; frame <= 30; ++frame) {
    for (int s = 0; s < probe.steps_per_frame; ++s) {
      sim.advance(1);
      const SkinContact& c = *sim.contact();
      worst_balance = std::max(worst_balance, (c.tool_force(0) + sim.external_on_body()).norm());
      scale = std::max(scale, c.tool_force(0).norm());
      deepest = std::max(deepest, c.max_depth(0));
      fz.push_back(c.tool_force(0).z());
      for (int v = 0; v < c.map().size(); ++v)
        if (c.vertex_force()[v].squaredNorm() > 0) {
          ++touching;
          touching_on_coarse += c.map().level(v) != sim.num_levels() - 1;
        }
    }
    events.clear();
    adapt.update(sim, frame, events);
    if (!events.empty()) changed.push_back(static_cast<int>(fz.size()) - 1);
  }
  // Jumps of the force between consecutive steps: at the topology changes and elsewhere
  // while the probe slides at constant depth (t > 0.12 s).
  const int sliding_from = static_cast<int>(0.12 / probe.setup.dt);
  double jump_at_change = 0, jump_elsewhere = 0, mean = 0;
  int n = 0;
  for (int i = sliding_from; i + 1 < static_cast<int>(fz.size()); ++i) {
    const double jump = std::abs(fz[i + 1] - fz[i]);
    const bool at_change = std::find(changed.begin(), changed.end(), i) != changed.end();
    (at_change ? jump_at_change : jump_elsewhere) = std::max(at_change ? jump_at_change : jump_elsewhere, jump);
    mean += fz[i];
    ++n;
  }
  mean /= n;
  std::printf("sliding probe: %zu topology changes; |F_tool + F_body| <= %.2e of %.3e N; "
              "contacts on a coarser level %d of %d; mean F_z %.4e N; largest step-to-step jump "
              "at a change %.3e N (%.2f %% of the mean), elsewhere %.3e N; penetration %.4f mm\n",
              changed.size(), worst_balance, scale, touching_on_coarse, touching, mean,
              jump_at_change, 100 * jump_at_change / mean, jump_elsewhere, deepest * 1e3);
  EXPECT_GT(changed.size(), 5u);
  EXPECT_LT(worst_balance, 1e-12 * scale);
  EXPECT_EQ(touching_on_coarse, 0);
  // The skin is coarse under the probe (contact radius 2 mm, 1.2 mm cells): vertices entering
  // and leaving contact already make the force step by several % while it slides.
  EXPECT_LT(jump_at_change, 0.10 * mean);
  EXPECT_LT(jump_at_change, 1.5 * jump_elsewhere);
}

// The skin follows the hierarchy's own interpolation (a skin vertex that is a finest point,
// active or ghost, has exactly that point's displacement), and the contact forces reach the
// active points through the transpose of that map: for any virtual displacement of the active
// points the work on the skin equals the work of the forces the simulation applied.
TEST(ToolContact, NestedLevelsRunTheSlidingProbeAtTheirStableStepEstimate) {
  // Issue 15 point 1: with lumped masses, nested 4/8/16-cell levels blew up under the energy
  // couplings at the Courant estimate when the finest level first became active, and ran at a
  // quarter of it. With interface masses they run at the largest stable step estimate of the
  // level points and the contact at set-up, fixed (no adaptation), for the whole slide.
  for (Coupling coupling : {Coupling::Energy, Coupling::EnergyConsistent}) {
    SlidingProbe probe(coupling, {4, 8, 16});
    HierarchicalSimulation probe_sim(probe.pointers(), probe.setup);
    // The set-up estimate of every point of every level with its whole star (the contact bound
    // of simulation/stable_step.cpp would only lower it), fixed for the whole run.
    double dt = INFINITY;
    for (int l = 0; l < probe_sim.num_levels(); ++l)
      for (const PointInertia& p : probe_sim.model(l).star)
        dt = std::min(dt, stable_step_of(p, false));
    probe.steps_per_frame = static_cast<int>(std::ceil(probe.frame / dt));
    probe.setup.dt = probe.frame / probe.steps_per_frame;
    probe.setup.steps_per_frame = probe.steps_per_frame;
    HierarchicalSimulation sim(probe.pointers(), probe.setup);
    SpaceAdaptivity adapt(probe.adaptivity(), sim);
    std::vector<HierarchyEvent> events;
    int splits = 0;
    double fine_active = 0, peak = 0;
    for (int frame = 1; frame <= 30; ++frame) {
      sim.advance_frame();
      events.clear();
      adapt.update(sim, frame, events);
      for (const HierarchyEvent& e : events) splits += e.kind == "split";
      fine_active = std::max(fine_active, static_cast<double>(sim.lists().active(2).size()));
      peak = std::max(peak, sim.contact()->tool_force(0).norm());
      for (int l = 0; l < sim.num_levels(); ++l)
        for (int p : sim.lists().active(l))
          ASSERT_TRUE(sim.state(l).v[p].allFinite()) << "frame " << frame << " level " << l;
    }
    EXPECT_GT(splits, 10);
    EXPECT_GT(fine_active, 0);
    const Energies e = hierarchy_energies(sim);
    EXPECT_LT(e.kinetic, 1e-3) << "a growing mode";  // pressed slowly: micro-joules at most
    EXPECT_GT(peak, 0.0);
    const double old_courant = courant_dt(probe.meshes.back(), probe.setup.law);
    RecordProperty("step_over_old_courant", std::to_string(probe.setup.dt / old_courant));
  }
}

TEST(ToolContact, SkinFollowsTheHierarchyAndContactForcesDoItsVirtualWork) {
  SlidingProbe probe(Coupling::Energy);
  HierarchicalSimulation sim(probe.pointers(), probe.setup);
  SpaceAdaptivity adapt(probe.adaptivity(), sim);
  std::vector<HierarchyEvent> events;
  for (int frame = 1; frame <= 8; ++frame) {  // the probe presses; levels mixed under it
    sim.advance_frame();
    adapt.update(sim, frame, events);
  }
  sim.advance(1);
  const SkinContact& c = *sim.contact();
  ASSERT_GT(c.tool_force(0).norm(), 0);
  const int fine = sim.num_levels() - 1;
  const TetMesh& fine_mesh = *sim.model(fine).mesh;
  std::vector<Vec3> u, v;
  sim.skin_state(u, v);
  int ghosts = 0;
  double worst = 0, scale = 0;
  for (int s = 0; s < c.map().size(); ++s) {
    if (c.map().level(s) != fine) continue;
    for (int p = 0; p < static_cast<int>(fine_mesh.points.size()); ++p)
      if ((fine_mesh.points[p] - c.skin().rest[s]).norm() < 1e-12) {
        const NodeState st = sim.hierarchy().state(fine, p);
        ghosts += st == NodeState::GhostIface;
        worst = std::max(worst, (u[s] - sim.state(fine).u[p]).norm());
        scale = std::max(scale, u[s].norm());
      }
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> r(-1, 1);
  std::vector<std::vector<Vec3>> du(sim.num_levels()), dv(sim.num_levels());
  std::vector<LevelFields> fields;
  double on_active = 0, on_skin = 0;
  for (int l = 0; l < sim.num_levels(); ++l) {
    du[l].assign(sim.model(l).num_points(), Vec3::Zero());
    dv[l] = du[l];
    for (int p : sim.lists().active(l)) {
      if (sim.state(l).free_point[p]) du[l][p] = Vec3(r(rng), r(rng), r(rng));
      on_active += sim.external_force(l)[p].dot(du[l][p]);
    }
    fields.push_back({du[l].data(), dv[l].data()});
  }
  int through_ghosts = 0;
  for (int s = 0; s < c.map().size(); ++s) {
    if (c.vertex_force()[s].squaredNorm() == 0) continue;
    on_skin += c.vertex_force()[s].dot(c.map().value(s, fields, false));
    for (const ActiveTerm& t : c.map().row(s)) through_ghosts += t.level != c.map().level(s);
  }
  std::printf("skin = finest point: worst %.2e of %.2e m (%d of them interface ghosts); virtual "
              "work on the skin %.9e, on the active points %.9e; %d contact terms through "
              "another level\n",
              worst, scale, ghosts, on_skin, on_active, through_ghosts);
  EXPECT_GT(ghosts, 0);
  EXPECT_LE(worst, 1e-14 * scale);
  EXPECT_NEAR(on_skin, on_active, 1e-12 * std::abs(on_skin));
  EXPECT_GT(std::abs(on_skin), 0);
}

// The skin's positions interpolated for the refinement's look-ahead (contact_region) serve the
// next frame's broad phase only while the state is the same (SkinContact::near_tools' version):
// a run that asked for the look-ahead finds the same candidates as one that did not, with and
// without the points edited in between; an edit that was missed would keep the old skin.
TEST(ToolContact, TheLookAheadsSkinPositionsServeTheBroadPhaseOnlyForTheSameState) {
  SlidingProbe probe(Coupling::Energy);
  const auto candidates = [&](bool look_ahead, bool edit) {
    HierarchicalSimulation sim(probe.pointers(), probe.setup);
    sim.advance(probe.steps_per_frame);  // the probe is above the skin
    std::vector<std::pair<int, int>> region;
    if (look_ahead) sim.contact_region(3 * probe.frame, region);
    if (edit)  // the whole body 1.5 mm up, into the probe's reach
      for (int l = 0; l < sim.num_levels(); ++l)
        for (int p : sim.lists().active(l))
          if (sim.state(l).free_point[p]) sim.state(l).u[p] += Vec3(0, 0, 1.5e-3);
    sim.advance(1);  // its frame's broad phase, then one step
    return sim.contact()->candidates();
  };
  const auto plain = candidates(false, false);
  EXPECT_EQ(candidates(true, false), plain);
  const auto edited = candidates(false, true);
  EXPECT_NE(edited, plain);  // the edit matters to the broad phase
  EXPECT_EQ(candidates(true, true), edited);
}

}  // namespace
}  // namespace mrsim
