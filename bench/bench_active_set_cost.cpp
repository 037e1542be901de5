// A step costs O(active + ghosts), never O(all points) (issue 4 point 5): three box levels, the
// finest one larger at each argument (n cells along x: 32, 64, 96, 128, i.e. 9.5 k to 545 k
// points), with the same number of finest points active (a corner region of ~2000 points,
// smaller as the mesh gets finer). Per-step time must stay flat while the finest level grows.
//   build/bench/bench_active_set_cost
#include <benchmark/benchmark.h>

#include <algorithm>

#include "mesh/box_mesh.hpp"
#include "simulation/hierarchical_simulation.hpp"

using namespace mrsim;

namespace {

constexpr std::size_t kActiveFine = 2000;

// Splits, nearest to the corner first, the finest level that can still refine, until the
// finest level has kActiveFine active points.
void refine_corner(HierarchicalSimulation& sim) {
  const int fine = sim.num_levels() - 1;
  while (sim.lists().active(fine).size() < kActiveFine) {
    bool split = false;
    for (int l = fine - 1; l >= 0 && !split; --l) {
      int best = -1;
      double best_d = 1e300;
      for (int p : sim.lists().active(l)) {
        const double d = sim.model(l).mesh->points[p].squaredNorm();
        if (d < best_d && sim.hierarchy().can_split(l, p)) {
          best = p;
          best_d = d;
        }
      }
      if (best >= 0) {
        sim.split(l, best);
        split = true;
      }
    }
    if (!split) break;
    sim.apply_changes();
  }
}

void active_set_step(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Vec3 lo(0, 0, 0), hi(0.2, 0.1, 0.1);
  const std::vector<TetMesh> meshes = {make_box_mesh(lo, hi, 4, 2, 2), make_box_mesh(lo, hi, 12, 6, 6),
                                       make_box_mesh(lo, hi, n, n / 2, n / 2)};
  HierarchySetup hs;
  hs.law.strain = StrainMeasure::GreenLagrange;
  hs.law.lambda = 5.0e4;
  hs.law.mu = 2.0e4;
  hs.law.psi = 2;
  hs.gravity = Vec3(0, 0, -9.81);
  hs.dt = 1e-6;
  HierarchicalSimulation sim({&meshes[0], &meshes[1], &meshes[2]}, hs);
  refine_corner(sim);
  std::size_t active = 0, ghosts = 0;
  for (int l = 0; l < 3; ++l)
    active += sim.lists().active(l).size(),
        ghosts += sim.lists().ghost_sub(l).size() + sim.lists().ghost_iface(l).size();
  for (auto _ : state) sim.advance(10);
  state.SetItemsProcessed(state.iterations() * 10);  // steps: "Time" is that of 10 steps
  state.counters["finest_points"] = static_cast<double>(meshes[2].points.size());
  state.counters["active"] = static_cast<double>(active);
  state.counters["ghosts"] = static_cast<double>(ghosts);
}

}  // namespace

BENCHMARK(active_set_step)->Arg(32)->Arg(64)->Arg(96)->Arg(128)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
