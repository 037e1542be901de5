#pragma once
// Deterministic, easily recomputed point data for writer tests: every value depends on the
// level, the frame and the point index, with non-round doubles so that any precision loss
// (float conversion, text formatting) shows up as a mismatch.
#include <cmath>
#include <cstdint>
#include <vector>

#include "io/frame_data.hpp"
#include "mesh/box_mesh.hpp"

namespace mrsim::test {

/// The times of the three frames written by the tests. The third is one ulp above 0.08 (what
/// accumulating 0.04 steps easily gives): any text form short of full precision loses it.
inline constexpr double kSampleTimes[3] = {0.0, 0.04, 0.08000000000000002};

inline TetMesh sample_mesh(int level) {
  // Level k has 2^k cells per side along x: 1x1x1 then 2x1x1, small and distinct.
  return make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.03), 1 << level, 1, 1);
}

struct SampleLevel {
  TetMesh mesh;
  std::vector<Vec3> displacement, velocity, force;
  std::vector<std::int8_t> status;
  std::vector<std::int32_t> time_level;
  std::vector<double> criterion, mass;

  SampleLevel(int level, int frame) : mesh(sample_mesh(level)) {
    const std::size_t n = mesh.points.size();
    for (std::size_t i = 0; i < n; ++i) {
      const double s = static_cast<double>(i) + 0.1 * level + 0.01 * frame;
      displacement.emplace_back(1e-3 * std::sin(s), -2e-3 * std::cos(s), 1e-4 * frame / 3.0);
      velocity.emplace_back(std::sin(2 * s), 0.5 * frame, -1.0 / (s + 1));
      force.emplace_back(-9.81 * s, 1e-6 * s, std::exp(-s));
      status.push_back(static_cast<std::int8_t>((i + static_cast<std::size_t>(frame)) % 3));
      time_level.push_back(static_cast<std::int32_t>(i % 4) + frame);
      criterion.push_back(s / 7.0);
      mass.push_back(1.0 / (s + 3.0));
    }
  }

  LevelFrameView view() const {
    LevelFrameView v;
    v.mesh = &mesh;
    v.displacement = displacement;
    v.velocity = velocity;
    v.force = force;
    v.status = status;
    v.time_level = time_level;
    v.criterion = criterion;
    v.mass = mass;
    return v;
  }
};

/// Both levels of one frame (the views refer into the returned levels: keep them alive).
inline std::vector<SampleLevel> sample_frame(int frame) {
  return {SampleLevel(0, frame), SampleLevel(1, frame)};
}

inline std::vector<LevelFrameView> views_of(const std::vector<SampleLevel>& levels) {
  std::vector<LevelFrameView> views;
  for (const SampleLevel& level : levels) views.push_back(level.view());
  return views;
}

}  // namespace mrsim::test
