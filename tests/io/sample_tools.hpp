#pragma once
// Deterministic skin, tool and tool-sample data for writer tests, in the spirit of
// sample_frames.hpp: every value depends on the tool, the frame and the index, with non-round
// doubles so that any precision loss or mix-up of rows shows as a mismatch.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "io/frame_data.hpp"

namespace mrsim::test {

using Triangle = std::array<int, 3>;

/// The skin of a small box (8 corners, 12 outward triangles), moved a little at each frame.
struct SampleSurface {
  std::vector<Vec3> rest, displacement, velocity, contact_force;
  std::vector<Triangle> triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7},
                                     {0, 1, 5}, {0, 5, 4}, {3, 7, 6}, {3, 6, 2},
                                     {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
  std::vector<std::int8_t> level;

  explicit SampleSurface(int frame) {
    for (int i = 0; i < 8; ++i) {
      const double s = i + 0.01 * frame;
      rest.emplace_back(0.1 * ((i + 1) / 2 % 2), 0.02 * (i / 2 % 2), 0.03 * (i / 4));
      displacement.emplace_back(1e-3 * std::sin(s), 2e-3 * std::cos(s), -1e-4 * frame / 3.0);
      velocity.emplace_back(std::cos(3 * s), -0.25 * frame, 1.0 / (s + 2));
      contact_force.emplace_back(0.0, i % 3 == 0 ? -std::sqrt(s + 1) : 0.0, 1e-7 * s);
      level.push_back(static_cast<std::int8_t>(i % 2));
    }
  }

  SurfaceFrameView view() const {
    SurfaceFrameView v;
    v.rest = rest;
    v.triangles = triangles;
    v.displacement = displacement;
    v.velocity = velocity;
    v.contact_force = contact_force;
    v.level = level;
    return v;
  }
};

/// Tool 0 is a tetrahedron (4 points, 4 triangles), tool 1 a square pyramid (5 points,
/// 6 triangles): different counts, so a wrong point offset in the shared block shows.
struct SampleTool {
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  Vec3 force;

  SampleTool(int tool, int frame) {
    const Vec3 origin(0.05 + 0.3 * tool, 0.01, 0.04 - 1e-3 * frame / 7.0);
    if (tool == 0) {
      for (const Vec3& p : {Vec3(0, 0, 0), Vec3(0.01, 0, 0.02), Vec3(0, 0.01, 0.02),
                            Vec3(-0.01, -0.01, 0.02)}) {
        points.push_back(origin + p);
      }
      triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 3}, {1, 2, 3}};
    } else {
      for (const Vec3& p : {Vec3(0, 0, 0), Vec3(0.01, 0.01, 0.02), Vec3(-0.01, 0.01, 0.02),
                            Vec3(-0.01, -0.01, 0.02), Vec3(0.01, -0.01, 0.02)}) {
        points.push_back(origin + p);
      }
      triangles = {{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 1, 4}, {1, 2, 3}, {1, 3, 4}};
    }
    force = Vec3(0.1 * tool - 1.0 / 3.0, std::sqrt(2.0) * frame, -9.81 / (tool + frame + 1));
  }

  ToolFrameView view() const {
    ToolFrameView v;
    v.points = points;
    v.triangles = triangles;
    v.force = force;
    return v;
  }
};

inline std::vector<SampleTool> sample_tools(int frame) {
  return {SampleTool(0, frame), SampleTool(1, frame)};
}

inline std::vector<ToolFrameView> views_of(const std::vector<SampleTool>& tools) {
  std::vector<ToolFrameView> views;
  for (const SampleTool& tool : tools) views.push_back(tool.view());
  return views;
}

/// The samples of one tool during one frame: `steps` rows, their values depending on the
/// tool and on the global sample number `first + s`, so concatenated frames are checkable.
struct SampleSteps {
  std::vector<double> time;
  std::vector<Vec3> position, force;
  std::vector<std::array<double, 4>> orientation;
  std::vector<std::int32_t> contacts;

  SampleSteps(int tool, int first, int steps) {
    for (int s = first; s < first + steps; ++s) {
      const double a = 0.01 * s + 0.5 * tool;
      time.push_back(s * 1e-3 / 3.0);
      position.emplace_back(0.3 * tool, std::sin(a), -a / 7.0);
      orientation.push_back({std::cos(a / 2), 0.0, std::sin(a / 2), 0.0});
      force.emplace_back(1e-3 * s, -std::exp(-a), tool - 0.1 * s);
      contacts.push_back(s * 3 + tool);
    }
  }

  ToolSamples view() const {
    ToolSamples v;
    v.time = time;
    v.position = position;
    v.orientation = orientation;
    v.force = force;
    v.contacts = contacts;
    return v;
  }
};

}  // namespace mrsim::test
