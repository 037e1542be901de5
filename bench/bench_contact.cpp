// The cost of the tool (issue 6, method.md §6.2): the per-step penalty contact on the broad
// phase's candidates, the per-frame broad phase over the whole skin, the per-topology-change
// skin map, against one simulation step of the same hierarchy with and without the tool.
// Three independent box levels (9, 17, 33 cells across a 10 x 10 x 5 cm block; the finest skin
// has 4.6 k vertices), a sphere of radius 1 cm pressed 3 mm into the top face, the finest level
// active under it.
//   build/bench/bench_contact
#include <benchmark/benchmark.h>

#include <memory>

#include "mesh/box_mesh.hpp"
#include "simulation/hierarchical_simulation.hpp"
#include "simulation/space_adaptivity.hpp"

using namespace mrsim;

namespace {

struct PressedBlock {
  std::vector<TetMesh> meshes;
  std::unique_ptr<HierarchicalSimulation> sim;
  std::vector<std::vector<Vec3>> external;
  std::vector<Vec3*> external_ptrs;
  std::vector<LevelFields> fields;

  explicit PressedBlock(bool with_tool) {
    for (int n : {9, 17, 33})
      meshes.push_back(make_box_mesh(Vec3(-0.05, -0.05, -0.05), Vec3(0.05, 0.05, 0), n, n, (n + 1) / 2));
    HierarchySetup hs;
    hs.law.strain = StrainMeasure::GreenLagrange;
    hs.law.lambda = 4.0e4;
    hs.law.mu = 1.0e4;
    hs.law.psi = 1;
    for (const TetMesh& m : meshes) {
      std::vector<std::uint8_t> fixed(m.points.size(), 0);
      for (size_t p = 0; p < m.points.size(); ++p) fixed[p] = m.points[p].z() < -0.05 + 1e-9;
      hs.fixed.push_back(fixed);
    }
    hs.dt = 2e-5;
    hs.steps_per_frame = 1000;
    if (with_tool) {
      Tool tool;
      tool.name = "probe";
      tool.shape = {ToolShapeKind::Sphere, 0.01, 0};
      tool.trajectory = ToolTrajectory({{0.0, Vec3(0, 0, 0.013)}, {0.02, Vec3(0, 0, 0.007)}},
                                       Interpolation::Smooth, "probe");
      hs.tools.push_back(tool);
    }
    sim = std::make_unique<HierarchicalSimulation>(
        std::vector<const TetMesh*>{&meshes[0], &meshes[1], &meshes[2]}, hs);
    // Refine around the tool's region (with or without it), then press for a frame.
    SpaceAdaptivitySettings s;
    s.enabled = true;
    s.refine_above = 1e9;
    s.contact_lookahead = 0.1;
    SpaceAdaptivity adapt(s, *sim);
    std::vector<HierarchyEvent> events;
    if (with_tool)
      for (int f = 0; f < 3; ++f) adapt.update(*sim, f, events);
    sim->advance_frame();
    for (int l = 0; l < 3; ++l) {
      external.emplace_back(meshes[l].points.size(), Vec3::Zero());
      external_ptrs.push_back(external.back().data());
      fields.push_back({sim->state(l).u.data(), sim->state(l).v.data()});
    }
  }
};

void contact_step(benchmark::State& state) {
  PressedBlock b(true);
  SkinContact& c = *b.sim->contact();
  c.begin_frame(b.sim->time(), b.sim->time() + 0.02, b.fields);
  for (auto _ : state) {
    c.clear(b.external_ptrs);
    benchmark::DoNotOptimize(c.apply(b.sim->time(), b.fields, b.external_ptrs));
  }
  c.apply(b.sim->time(), b.fields, b.external_ptrs);
  int touching = 0;
  for (const Vec3& f : c.vertex_force()) touching += f.squaredNorm() > 0;
  state.counters["skin"] = c.map().size();
  state.counters["contacts"] = touching;
  state.counters["finest_active"] = static_cast<double>(b.sim->lists().active(2).size());
}

void broad_phase(benchmark::State& state) {
  PressedBlock b(true);
  SkinContact& c = *b.sim->contact();
  for (auto _ : state) c.begin_frame(b.sim->time(), b.sim->time() + 0.02, b.fields);
  state.counters["skin"] = c.map().size();
}

void skin_remap(benchmark::State& state) {
  PressedBlock b(true);
  SkinContact& c = *b.sim->contact();
  std::vector<const std::vector<std::uint8_t>*> free;
  for (int l = 0; l < 3; ++l) free.push_back(&b.sim->state(l).free_point);
  c.begin_frame(b.sim->time(), b.sim->time() + 0.02, b.fields);
  // What a topology change costs the contact: the map, then the rows its candidates use.
  std::size_t terms = 0;
  for (auto _ : state) {
    c.remap(b.sim->hierarchy(), free);
    for (const std::vector<int>& tool : c.candidates())
      for (int s : tool) terms += c.map().row(s).size();
  }
  benchmark::DoNotOptimize(terms);
  state.counters["candidates"] = static_cast<double>(c.candidates()[0].size());
}

// 50 whole steps (forces, kicks, drifts, ghosts, contact; one broad phase) of the hierarchy.
void fifty_steps(benchmark::State& state) {
  PressedBlock b(true);
  for (auto _ : state) b.sim->advance(50);
  std::size_t active = 0;
  for (int l = 0; l < 3; ++l) active += b.sim->lists().active(l).size();
  state.counters["active"] = static_cast<double>(active);
}

}  // namespace

BENCHMARK(contact_step)->Unit(benchmark::kMicrosecond);
BENCHMARK(broad_phase)->Unit(benchmark::kMicrosecond);
BENCHMARK(skin_remap)->Unit(benchmark::kMicrosecond);
BENCHMARK(fifty_steps)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
