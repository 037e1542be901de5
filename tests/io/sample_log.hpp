#pragma once
// The log.h5 header and per-frame records of the writer tests (levels from sample_frames.hpp),
// shared by the tests of the core log and of its tool groups.
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "io/hdf5_log.hpp"
#include "sample_frames.hpp"

namespace mrsim::test {

inline const char* const kScenario = "name: beam\nmaterial:\n  mu: 1.0e+4  # µ, Pa\n";

struct LogFixture {
  std::vector<SampleLevel> first = sample_frame(0);
  std::vector<ToolLogInfo> tools;  // none unless a test adds some

  Hdf5LogHeader header() const {
    Hdf5LogHeader h;
    h.version = "0.1.0";
    h.git_revision = "abc1234";
    h.scenario_yaml = kScenario;
    h.start_time = "2026-01-02T03:04:05Z";
    for (const auto& level : first) h.levels.push_back(&level.mesh);
    h.time_level_steps = {0.04, 0.02, 0.01};
    h.tools = tools;
    return h;
  }
};

/// Force on tool `tool` at the end of frame `frame` (non-round, distinct per tool and frame).
inline Vec3 sample_tool_force(int frame, int tool) {
  return Vec3(frame + 0.5 * tool, -1.0 / (tool + 3), 1e-3 * std::sqrt(frame + tool + 1.0));
}

// Per-frame values with something to lose: non-round doubles and counters above 2^31.
inline FrameRecord sample_record(int f, const std::vector<SampleLevel>& levels,
                                 std::size_t tools = 0) {
  FrameRecord r;
  r.frame = f;
  r.time = kSampleTimes[f];
  r.kinetic_energy = 0.5 * f / 3.0;
  r.elastic_energy = std::sqrt(2.0) * f;
  r.wall_time = 1e-3 * (f + 1) / 7.0;
  r.active = {8 - f, 12 + f};
  r.ghosts = {f, 2 * f};
  r.force_evaluations = {1000LL * f, (1LL << 40) + f};
  r.tet_updates = {5000LL * f, (1LL << 41) + 3 * f};
  r.time_levels = {3 + f, 0, 7 * f};
  r.time_level_evaluations = {11LL * f, (1LL << 41) + f, 0};
  for (std::size_t k = 0; k < tools; ++k) {
    r.tool_force.push_back(sample_tool_force(f, static_cast<int>(k)));
  }
  for (const auto& level : levels) r.status.emplace_back(level.status);
  return r;
}

inline void append_sample_frame(Hdf5Log& log, int f, std::size_t tools = 0) {
  const auto levels = sample_frame(f);
  log.append_frame(sample_record(f, levels, tools));
}

}  // namespace mrsim::test
