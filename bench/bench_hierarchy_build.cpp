// Hierarchy precomputation cost (issue 4 point 1): point adjacency + links between levels
// (point location, Voronoi parents, active/ghost sets) for three box levels totalling ~1 M tets.
//   build/bench/bench_hierarchy_build
#include <benchmark/benchmark.h>

#include "hierarchy/level_links.hpp"
#include "mesh/box_mesh.hpp"

using namespace mrsim;

namespace {

void hierarchy_build(benchmark::State& state) {
  const Vec3 lo(0, 0, 0), hi(0.3, 0.3, 0.2);
  // 13 500 + 113 400 + 907 200 = 1 034 100 tets; distinct resolutions, not nested.
  const std::vector<TetMesh> meshes = {make_box_mesh(lo, hi, 15, 15, 10),
                                       make_box_mesh(lo, hi, 30, 30, 21),
                                       make_box_mesh(lo, hi, 60, 60, 42)};
  std::int64_t tets = 0;
  for (const auto& m : meshes) tets += static_cast<std::int64_t>(m.tets.size());
  for (auto _ : state) {
    std::vector<PointAdjacency> adj;
    std::vector<HierarchyLevel> levels;
    for (const auto& m : meshes)
      adj.push_back(build_point_adjacency(static_cast<int>(m.points.size()), m.tets));
    for (size_t l = 0; l < meshes.size(); ++l) levels.push_back({&meshes[l], &adj[l]});
    auto links = build_level_links(levels);
    benchmark::DoNotOptimize(links.data());
  }
  state.counters["tets"] = static_cast<double>(tets);
}

}  // namespace

BENCHMARK(hierarchy_build)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);
BENCHMARK_MAIN();
