// Set-up cost of the bundled liver's levels (issue 17 point 1: the whole process, set-up
// included, must follow the work): each level's model (geometry, adjacency, edge operators,
// bounds and spectra) with liver_probe's material (Green–Lagrange, E = 30 kPa, ν = 0.4,
// ψ = 5 Pa·s), and its parts: the stiffness spectrum and the combined damping/stiffness limit.
//   build/bench/bench_level_setup
#include <benchmark/benchmark.h>

#include "bundled_liver.hpp"
#include "physics/level_model.hpp"
#include "physics/spectral_bound.hpp"

using namespace mrsim;

namespace {

MaterialLaw liver_probe_law() {
  const double E = 3.0e4, nu = 0.4;
  MaterialLaw law;
  law.lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  law.mu = E / (2 * (1 + nu));
  law.psi = 5.0;
  law.density = 1000;
  return law;
}

const TetMesh& liver(int level) { return bench::bundled_liver_levels()[level]; }

void level_model(benchmark::State& state) {
  const TetMesh& mesh = liver(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    LevelModel m = build_level_model(mesh, liver_probe_law(), false);
    benchmark::DoNotOptimize(m.step_damping_scale);
  }
  state.counters["tets"] = static_cast<double>(mesh.tets.size());
}

void stiffness_spectrum(benchmark::State& state) {
  const LevelModel m = build_level_model(liver(3), liver_probe_law(), false);
  for (auto _ : state) benchmark::DoNotOptimize(largest_mass_scaled_eigenvalue(m.adj, m.K, m.mass));
}

void combined_limit(benchmark::State& state) {
  const bool filtered = state.range(0) != 0;
  const LevelModel m = build_level_model(liver(3), liver_probe_law(), filtered);
  const double k = filtered ? m.filter_spectrum.eigenvalue : m.stiffness_spectrum.eigenvalue;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        combined_step_limit(m.adj, m.K, m.D, m.mass, filtered, k, m.damping_spectrum.eigenvalue));
}

}  // namespace

BENCHMARK(level_model)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(stiffness_spectrum)->Unit(benchmark::kMillisecond);
BENCHMARK(combined_limit)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
