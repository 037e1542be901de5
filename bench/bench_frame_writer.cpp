// The VTK frames of the bundled liver's four levels (liver_probe's frames without its surface
// and tool blocks), written as a run writes them: one series of eight frames per iteration,
// the cells, masses and statuses the same from frame to frame, the motion not. Counters: the
// time and bytes of one frame, and the compressed blocks that were taken from the frame before
// (io/vtk_repeat_compressor.hpp). Writes under $TMPDIR (default /tmp), which it cleans.
//   build/bench/bench_frame_writer [--benchmark_filter=lz4]
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "bundled_liver.hpp"
#include "io/vtk_series_writer.hpp"

using namespace mrsim;

namespace {

constexpr int kFramesPerSeries = 8;

struct LevelFields {
  std::vector<Vec3> u, v, f;
  std::vector<std::int8_t> status;
  std::vector<std::int32_t> time_level;
  std::vector<double> criterion, mass, simulated;
  std::vector<std::int8_t> simulated_by;
};

// A smooth motion that changes every frame; everything else fixed, as between topology changes.
void move(const TetMesh& mesh, int frame, LevelFields& x) {
  const std::size_t n = mesh.points.size();
  x.u.resize(n);
  x.v.resize(n);
  x.f.assign(n, Vec3::Zero());
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& p = mesh.points[i];
    const double phase = 40.0 * p.x() + 30.0 * p.y() + 0.3 * frame;
    x.u[i] = 1e-3 * Vec3(std::sin(phase), std::cos(phase), std::sin(2 * phase));
    x.v[i] = 1e-2 * Vec3(std::cos(phase), -std::sin(phase), std::cos(2 * phase));
  }
}

LevelFields fixed_fields(const TetMesh& mesh, int level) {
  LevelFields x;
  const std::size_t n = mesh.points.size(), t = mesh.tets.size();
  x.status.assign(n, static_cast<std::int8_t>(level == 0 ? 2 : 0));
  x.time_level.assign(n, level == 0 ? 0 : -1);
  x.criterion.assign(n, 0.0);
  x.mass.assign(n, 1e-3);
  x.simulated.assign(t, level == 0 ? 1.0 : 0.0);
  x.simulated_by.assign(t, 0);
  return x;
}

LevelFrameView view(const TetMesh& mesh, const LevelFields& x) {
  return {&mesh, x.u, x.v, x.f, x.status, x.time_level, x.criterion, x.mass, x.simulated,
          x.simulated_by};
}

std::uintmax_t folder_bytes(const std::filesystem::path& dir) {
  std::uintmax_t bytes = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file()) bytes += e.file_size();
  return bytes;
}

void series(benchmark::State& state, FrameCompression compression) {
  const auto& meshes = bench::bundled_liver_levels();
  std::vector<LevelFields> fields;
  for (std::size_t l = 0; l < meshes.size(); ++l)
    fields.push_back(fixed_fields(meshes[l], static_cast<int>(l)));
  const char* tmp = std::getenv("TMPDIR");
  const std::filesystem::path dir =
      std::filesystem::path(tmp ? tmp : "/tmp") / "mrsim_bench_frame_writer";
  std::size_t reused = 0, series_count = 0;
  std::uintmax_t bytes = 0;
  for (auto _ : state) {
    state.PauseTiming();
    std::filesystem::remove_all(dir);
    state.ResumeTiming();
    VtkSeriesWriter writer(dir, compression);
    for (int frame = 0; frame < kFramesPerSeries; ++frame) {
      std::vector<LevelFrameView> views;
      for (std::size_t l = 0; l < meshes.size(); ++l) {
        move(meshes[l], frame, fields[l]);
        views.push_back(view(meshes[l], fields[l]));
      }
      writer.write_frame(frame, 0.02 * frame, views);
    }
    state.PauseTiming();
    reused += writer.reused_blocks();
    bytes = folder_bytes(dir);
    ++series_count;
    state.ResumeTiming();
  }
  std::filesystem::remove_all(dir);
  state.SetItemsProcessed(state.iterations() * kFramesPerSeries);
  state.counters["bytes_per_frame"] = static_cast<double>(bytes) / kFramesPerSeries;
  state.counters["reused_blocks_per_frame"] =
      static_cast<double>(reused) / (static_cast<double>(series_count) * kFramesPerSeries);
}

void lz4(benchmark::State& state) { series(state, FrameCompression::Lz4); }
void zlib(benchmark::State& state) { series(state, FrameCompression::Zlib); }
void none(benchmark::State& state) { series(state, FrameCompression::None); }

}  // namespace

BENCHMARK(lz4)->Unit(benchmark::kMillisecond);
BENCHMARK(zlib)->Unit(benchmark::kMillisecond);
BENCHMARK(none)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
