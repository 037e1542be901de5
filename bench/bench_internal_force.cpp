// Elastic force throughput (issue 2 point 8): tet-updates per second, i.e. tets of the mesh
// times full force evaluations per second, for the Cauchy edge gather and the Green–Lagrange
// per-tet pass + gather, with and without damping, on one thread and on all threads.
//   build/bench_internal_force --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <random>

#include "core/parallel.hpp"
#include "mesh/box_mesh.hpp"
#include "physics/green_nodal_forces.hpp"
#include "physics/internal_force.hpp"

using namespace mrsim;

namespace {

// 32 x 32 x 18 cells x 6 = 110 592 tets, 20 691 points.
const TetMesh& mesh() {
  static const TetMesh m = make_box_mesh(Vec3(0, 0, 0), Vec3(0.32, 0.32, 0.18), 32, 32, 18);
  return m;
}

// The benchmarks' material: soft tissue, ψ = 20 Pa·s when damped.
MaterialLaw law(StrainMeasure strain, bool damped) {
  MaterialLaw m;
  m.strain = strain;
  m.lambda = 5.0e4;
  m.mu = 1.0e4;
  if (damped) m.psi = 20;
  return m;
}

// Displacements and velocities of n points, uniform in ±1 mm (m/s), the same every run.
void random_state(int n, std::vector<Vec3>& u, std::vector<Vec3>& v) {
  u.resize(n);
  v.resize(n);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> d(-1e-3, 1e-3);
  for (int i = 0; i < n; ++i) {
    u[i] = Vec3(d(rng), d(rng), d(rng));
    v[i] = Vec3(d(rng), d(rng), d(rng));
  }
}

void bench_forces(benchmark::State& state, StrainMeasure strain, bool damped) {
  const int threads = static_cast<int>(state.range(0));
  omp_set_num_threads(threads);
  set_parallel_threshold(1);
  const LevelModel model = build_level_model(mesh(), law(strain, damped));
  const int n = model.num_points();
  std::vector<Vec3> u, v, f(n);
  random_state(n, u, v);
  ForceWorkspace ws;
  double fastest = std::numeric_limits<double>::infinity();
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    internal_forces(model, u.data(), v.data(), f.data(), ws);
    benchmark::DoNotOptimize(f.data());
    benchmark::ClobberMemory();
    fastest = std::min(fastest, std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                                              start).count());
  }
  const double updates = static_cast<double>(state.iterations()) * model.num_tets();
  state.counters["tet_updates_per_s"] = benchmark::Counter(updates, benchmark::Counter::kIsRate);
  state.counters["per_core"] =
      benchmark::Counter(updates / threads, benchmark::Counter::kIsRate);
  // The fastest single evaluation (milliseconds of work): the kernel's own rate while the shared
  // host's other tenants leave the core and its caches alone. On the 2-vCPU AMD EPYC host the
  // calls of one run spread by a factor 1.6 (2.4-3.9 ms, green undamped), so the mean above says
  // as much about the neighbours as about the code (docs/performance.md, "Force kernels").
  state.counters["best_per_core"] = model.num_tets() / fastest / threads;
  state.counters["tets"] = model.num_tets();
}

// The Green–Lagrange per-tet pass alone (no gather), one thread, for each build of the kernel:
// what the AVX2 and AVX-512 builds chosen at run time gain over baseline x86-64 (same bits).
enum class Build { Baseline, Avx2, Avx512 };

void bench_green_pass(benchmark::State& state, Build build, bool damped) {
#if defined(__x86_64__)
  if (build == Build::Avx2 && !__builtin_cpu_supports("avx2")) {
    state.SkipWithError("no AVX2 on this processor");
    return;
  }
  if (build == Build::Avx512 && !has_avx512_kernel()) {
    state.SkipWithError("no AVX-512 (F, VL, DQ) on this processor");
    return;
  }
#endif
  const LevelModel model = build_level_model(mesh(), law(StrainMeasure::GreenLagrange, damped));
  std::vector<double> u(3 * model.num_points()), v(u.size());
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> d(-1e-3, 1e-3);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = d(rng), v[i] = d(rng);
  std::vector<int> tets(model.num_tets());
  for (int t = 0; t < model.num_tets(); ++t) tets[t] = t;
  std::vector<double> out(12 * tets.size());
  const GreenKernelData data = green_kernel_data(model);
  const auto kernel = build == Build::Avx512 ? &green_nodal_forces_avx512
                      : build == Build::Avx2 ? &green_nodal_forces_avx2
                                             : &green_nodal_forces_baseline;
  for (auto _ : state) {
    kernel(data, tets.data(), static_cast<int>(tets.size()),
           reinterpret_cast<const double(*)[3]>(u.data()),
           reinterpret_cast<const double(*)[3]>(v.data()),
           reinterpret_cast<double(*)[4][3]>(out.data()));
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["tet_updates_per_s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * model.num_tets(), benchmark::Counter::kIsRate);
}

// A partly simulated level's pass (issue 17 point 1): the live tets of the 600 points nearest the
// box's centre (a ball: scattered through the level's arrays), weighted and masked as at a level
// interface, damped, one thread, from a cold cache; read from the level's arrays (strided) or
// from their contiguous copy (physics/packed_tets.hpp; the same bits).
void bench_live_subset(benchmark::State& state, bool packed) {
  const LevelModel model =
      build_level_model(mesh(), law(StrainMeasure::GreenLagrange, true));
  const int n = model.num_points();
  std::vector<Vec3> u, v, f(n);
  random_state(n, u, v);
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  const Vec3 centre(0.16, 0.16, 0.09);
  std::partial_sort(order.begin(), order.begin() + 600, order.end(), [&](int a, int b) {
    return (mesh().points[a] - centre).squaredNorm() < (mesh().points[b] - centre).squaredNorm();
  });
  std::vector<int> points(order.begin(), order.begin() + 600), tets;
  std::sort(points.begin(), points.end());
  std::vector<unsigned char> mark(model.num_tets(), 0);
  live_tets(model, IndexSet::of(points), mark, tets);
  const std::vector<double> weight(model.num_tets(), 0.5);
  ForceWorkspace ws;
  if (packed) ws.packed.pack(model.geo, tets);
  // Between passes a step runs the other levels, the ghosts and the integrator: what the pass
  // reads is out of cache by the next one. A 64 MiB sweep stands for them (not timed).
  std::vector<char> sweep(64 << 20, 1);
  for (auto _ : state) {
    state.PauseTiming();
    for (std::size_t k = 0; k < sweep.size(); k += 64) sweep[k] = static_cast<char>(sweep[k] + 1);
    benchmark::DoNotOptimize(sweep.data());
    state.ResumeTiming();
    weighted_internal_forces(model, IndexSet::of(points), IndexSet::of(tets), weight.data(),
                             u.data(), v.data(), f.data(), ws);
    benchmark::DoNotOptimize(f.data());
    benchmark::ClobberMemory();
  }
  state.counters["tet_updates_per_s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * tets.size(), benchmark::Counter::kIsRate);
  state.counters["tets"] = static_cast<double>(tets.size());
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

BENCHMARK_CAPTURE(bench_green_pass, baseline, Build::Baseline, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(bench_green_pass, baseline_damped, Build::Baseline, true)
    ->Unit(benchmark::kMillisecond);
#if defined(__x86_64__)
BENCHMARK_CAPTURE(bench_green_pass, avx2, Build::Avx2, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(bench_green_pass, avx2_damped, Build::Avx2, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(bench_green_pass, avx512, Build::Avx512, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(bench_green_pass, avx512_damped, Build::Avx512, true)
    ->Unit(benchmark::kMillisecond);
#endif

BENCHMARK_CAPTURE(bench_live_subset, strided, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(bench_live_subset, packed, true)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
