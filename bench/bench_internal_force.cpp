// Elastic force throughput (issue 2 point 8): tet-updates per second, i.e. tets of the mesh
// times full force evaluations per second, for the Cauchy edge gather and the Green–Lagrange
// per-tet pass + gather, with and without damping, on one thread and on all threads.
//   build/bench_internal_force --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <omp.h>

#include <random>

#include "core/parallel.hpp"
#include "mesh/box_mesh.hpp"
#include "physics/internal_force.hpp"

using namespace mrsim;

namespace {

// 32 x 32 x 18 cells x 6 = 110 592 tets, 20 691 points.
const TetMesh& mesh() {
  static const TetMesh m = make_box_mesh(Vec3(0, 0, 0), Vec3(0.32, 0.32, 0.18), 32, 32, 18);
  return m;
}

void bench_forces(benchmark::State& state, StrainMeasure strain, bool damped) {
  const int threads = static_cast<int>(state.range(0));
  omp_set_num_threads(threads);
  set_parallel_threshold(1);
  MaterialLaw law;
  law.strain = strain;
  law.lambda = 5.0e4;
  law.mu = 1.0e4;
  if (damped) law.psi = 20;
  const LevelModel model = build_level_model(mesh(), law);
  const int n = model.num_points();
  std::vector<Vec3> u(n), v(n), f(n);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> d(-1e-3, 1e-3);
  for (int i = 0; i < n; ++i) {
    u[i] = Vec3(d(rng), d(rng), d(rng));
    v[i] = Vec3(d(rng), d(rng), d(rng));
  }
  ForceWorkspace ws;
  for (auto _ : state) {
    internal_forces(model, u.data(), v.data(), f.data(), ws);
    benchmark::DoNotOptimize(f.data());
    benchmark::ClobberMemory();
  }
  const double updates = static_cast<double>(state.iterations()) * model.num_tets();
  state.counters["tet_updates_per_s"] = benchmark::Counter(updates, benchmark::Counter::kIsRate);
  state.counters["per_core"] =
      benchmark::Counter(updates / threads, benchmark::Counter::kIsRate);
  state.counters["tets"] = model.num_tets();
}

void threads_arg(benchmark::internal::Benchmark* b) {
  b->Arg(1);
  if (omp_get_num_procs() > 1) b->Arg(omp_get_num_procs());
  b->UseRealTime()->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK_CAPTURE(bench_forces, cauchy, StrainMeasure::Cauchy, false)->Apply(threads_arg);
BENCHMARK_CAPTURE(bench_forces, cauchy_damped, StrainMeasure::Cauchy, true)->Apply(threads_arg);
BENCHMARK_CAPTURE(bench_forces, green, StrainMeasure::GreenLagrange, false)->Apply(threads_arg);
BENCHMARK_CAPTURE(bench_forces, green_damped, StrainMeasure::GreenLagrange, true)
    ->Apply(threads_arg);

BENCHMARK_MAIN();
