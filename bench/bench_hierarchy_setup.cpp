// Set-up of the bundled liver's hierarchy beyond its levels' models (issue 17 point 1: the
// whole process must follow the work): each level's point locator, the links between levels
// (every point located in the levels beside it), the boundary skin of the finest level and its
// binding in every level, as liver_probe builds them.
//   build/bench/bench_hierarchy_setup
#include <benchmark/benchmark.h>

#include "bundled_liver.hpp"
#include "contact/skin.hpp"
#include "contact/skin_binding.hpp"
#include "core/huge_page_heap.hpp"
#include "hierarchy/level_links.hpp"
#include "mesh/boundary_faces.hpp"

using namespace mrsim;

namespace {

struct Liver {
  const std::vector<TetMesh>& meshes = bench::bundled_liver_levels();
  std::vector<PointAdjacency> adj;
  std::vector<HierarchyLevel> levels;
};

const Liver& liver() {
  static const Liver l = [] {
    Liver v;
    for (const TetMesh& m : v.meshes)
      v.adj.push_back(build_point_adjacency(static_cast<int>(m.points.size()), m.tets));
    for (std::size_t k = 0; k < v.meshes.size(); ++k) v.levels.push_back({&v.meshes[k], &v.adj[k]});
    return v;
  }();
  return l;
}

std::vector<TetLocator> locators() {
  std::vector<TetLocator> out;
  for (const TetMesh& m : liver().meshes) out.emplace_back(m);
  return out;
}

void locator(benchmark::State& state) {
  const TetMesh& mesh = liver().meshes[state.range(0)];
  for (auto _ : state) {
    TetLocator loc(mesh);
    benchmark::DoNotOptimize(&loc);
  }
  state.counters["tets"] = static_cast<double>(mesh.tets.size());
}

void level_links(benchmark::State& state) {
  const auto loc = locators();
  for (auto _ : state) benchmark::DoNotOptimize(build_level_links(liver().levels, loc).data());
}

void finest_boundary_faces(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(boundary_faces(liver().meshes.back()).data());
}

void skin_binding(benchmark::State& state) {
  const auto loc = locators();
  const auto links = build_level_links(liver().levels, loc);
  const Skin skin = boundary_skin(liver().meshes.back());
  const bool reuse = state.range(0) != 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(bind_skin(skin, loc, reuse ? &links.back().parent_tet : nullptr));
  state.counters["vertices"] = static_cast<double>(skin.rest.size());
}

}  // namespace

BENCHMARK(locator)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);
BENCHMARK(level_links)->Unit(benchmark::kMillisecond);
BENCHMARK(finest_boundary_faces)->Unit(benchmark::kMicrosecond);
BENCHMARK(skin_binding)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
// The heap policy of mrsim's main(): without it every iteration would fault its arrays in again,
// and the page faults of this virtual machine would be most of what is measured.
int main(int argc, char** argv) {
  reserve_huge_page_heap(std::size_t{64} << 20);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
