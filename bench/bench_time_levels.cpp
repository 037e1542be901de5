// Frame cost with and without per-particle time levels on graded meshes (issue 5 point 5).
// The validation beam's box, 8 x 8 cells across, graded along x:
//   arg 0 "slab":      24 cells of w, 16 cells of w/8, 24 cells of w (two time levels apart by 3)
//   arg 1 "geometric": 40 cells shrinking by 0.9 each (w ... w/60: a mesh graded towards one end)
// Without time levels every particle takes the step of the smallest cells (the global Courant
// step); with them each takes its own (method.md §5.2), on the W-cycle (§5.4).
//   build/bench/bench_time_levels
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "mesh/box_mesh.hpp"
#include "simulation/hierarchical_simulation.hpp"
#include "time/time_level_rules.hpp"

using namespace mrsim;

namespace {

constexpr double kFrame = 1e-3;  // s: a short frame keeps the global run to ~1 s per frame

TetMesh graded(int kind) {
  std::vector<double> w;
  if (kind == 0) {
    w.assign(24, 1.0);
    w.insert(w.end(), 16, 1.0 / 8);
    w.insert(w.end(), 24, 1.0);
  } else {
    for (int i = 0; i < 40; ++i) w.push_back(std::pow(0.9, i));
  }
  return make_graded_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), w, 8, 8);
}

HierarchySetup setup(const TetMesh& mesh) {
  HierarchySetup s;
  s.law.strain = StrainMeasure::GreenLagrange;
  s.law.lambda = 5.77e5;
  s.law.mu = 3.85e5;
  s.law.psi = 0.5;
  s.gravity = Vec3(0, 0, -9.81);
  s.fixed.assign(1, std::vector<std::uint8_t>(mesh.points.size(), 0));
  for (size_t i = 0; i < mesh.points.size(); ++i) s.fixed[0][i] = mesh.points[i].x() < 1e-12;
  return s;
}

// The finest Courant level over the mesh: what the global step must use.
int finest_courant_level(const TetMesh& mesh, const HierarchySetup& s) {
  const LevelModel model = build_level_model(mesh, s.law);
  TimeLevelRules r;
  r.frame_dt = kFrame;
  r.max_level = 20;
  int k = 0;
  for (auto level : courant_levels(model, r)) k = std::max<int>(k, level);
  return k;
}

void frame(benchmark::State& state) {
  const TetMesh mesh = graded(static_cast<int>(state.range(0)));
  const bool adaptive = state.range(1) != 0;
  HierarchySetup s = setup(mesh);
  const int K = finest_courant_level(mesh, s);
  if (adaptive) {
    TimeLevelRules r;
    r.frame_dt = kFrame;
    r.max_level = K;
    s.time_levels = r;
  } else {
    s.steps_per_frame = 1 << K;
    s.dt = kFrame / s.steps_per_frame;
  }
  HierarchicalSimulation sim({&mesh}, s);
  sim.advance_frame();  // past the first transient
  const std::int64_t e0 = sim.force_evaluations(0);
  for (auto _ : state) sim.advance_frame();
  state.counters["points"] = static_cast<double>(mesh.points.size());
  state.counters["finest_level"] = K;
  state.counters["evals_per_frame"] =
      static_cast<double>(sim.force_evaluations(0) - e0) / static_cast<double>(state.iterations());
}

}  // namespace

BENCHMARK(frame)->ArgNames({"mesh", "time_levels"})->ArgsProduct({{0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
