#pragma once
// What the simulation hands to the writers for one display frame. Views only: the writers copy
// what they need, the simulation keeps ownership. Arrays are per point of one level.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/task_clock.hpp"
#include "core/vec.hpp"
#include "mesh/tet_mesh.hpp"

namespace mrsim {

/// Point status, as written to VTU `status` and HDF5 `/levels/level_k/status` (product.md).
enum class PointStatus : std::int8_t { Inactive = 0, Ghost = 1, Active = 2 };

struct LevelFrameView {
  const TetMesh* mesh = nullptr;            // rest positions and tets of this level
  std::span<const Vec3> displacement;       // m
  std::span<const Vec3> velocity;           // m/s
  std::span<const Vec3> force;              // N, total force last evaluated on each point
  std::span<const std::int8_t> status;      // PointStatus values
  std::span<const std::int32_t> time_level; // column of /frames/time_levels, -1: not integrated
  std::span<const double> criterion;        // h |Δu| (method.md §3.3)
  std::span<const double> mass;             // kg, lumped
  // Per tet: the share of its volume this level simulates, 0–1 (hierarchy/level_ownership.hpp).
  // Written as the cell array `simulated` when given (one value per tet); empty: not written.
  std::span<const double> simulated = {};
  // Per tet: the level that simulates most of it (cell array `simulated_by`; on the finest level
  // block, coloured by it, the object shows once, each part by its level). Empty: not written.
  std::span<const std::int8_t> simulated_by = {};
  // Per tet: the seven factors object.calibration: per_tet gives it on the level's tensor, on λ
  // and on the μ of xx, yy, zz, yz, xz, xy (cell array `calibration_scale`, 7 named components;
  // docs/hierarchy.md "Per-tet tensors"). Empty: not written.
  std::span<const std::array<double, 7>> calibration_scale = {};
};

/// The object's skin (the VTU `surface` block): a triangle surface moved by the levels.
struct SurfaceFrameView {
  std::span<const Vec3> rest;                        // m, rest positions
  std::span<const std::array<int, 3>> triangles;     // outward-oriented
  std::span<const Vec3> displacement;                // m
  std::span<const Vec3> velocity;                    // m/s
  std::span<const Vec3> contact_force;               // N, the tools' force on each vertex
  std::span<const std::int8_t> level;                // level whose tet moves each vertex
};

/// One tool as drawn in the VTU `tool` block (all tools share the block, cell array `tool`).
struct ToolFrameView {
  std::span<const Vec3> points;                      // m, world frame, posed
  std::span<const std::array<int, 3>> triangles;
  Vec3 force = Vec3::Zero();                         // N, force the object exerts on the tool
};

/// Samples of one tool at every simulation step of a frame (log.h5 `/tool*`, docs/output.md).
/// All spans have the same length S (possibly 0).
struct ToolSamples {
  std::span<const double> time;                          // s
  std::span<const Vec3> position;                        // m
  std::span<const std::array<double, 4>> orientation;    // unit quaternion w, x, y, z
  std::span<const Vec3> force;                           // N, the object's force on the tool
  std::span<const std::int32_t> contacts;                // skin vertices in contact
};

/// Per-frame scalars for `/frames/*` in log.h5. Vectors are indexed by level.
struct FrameRecord {
  int frame = 0;
  double time = 0;                 // s, simulated
  double kinetic_energy = 0;       // J
  double elastic_energy = 0;       // J
  double wall_time = 0;            // s, wall clock spent simulating this frame (0 at frame 0)
  TaskClock::Parts wall_time_parts{};  // s, the frame's wall time per task (core/task_clock.hpp)
  double stable_step = 0;          // s, the smallest stable step estimate in force at its end
  double step = 0;                 // s, the finest step the frame took
  Vec3 support_reaction = Vec3::Zero();  // N, force the fixed points exert on the body
  std::vector<std::int64_t> active;             // [L]
  std::vector<std::int64_t> ghosts;             // [L]
  std::vector<std::int64_t> force_evaluations;  // [L], cumulative point-force evaluations
  std::vector<std::int64_t> tet_updates;        // [L], cumulative per-tet stress evaluations
  std::vector<std::int64_t> time_levels;             // [C] particles per time level
  std::vector<std::int64_t> time_level_evaluations;  // [C] cumulative, per time level
  std::vector<Vec3> tool_force;  // [T] N, force on each tool at the frame's end (T may be 0)
  std::vector<std::span<const std::int8_t>> status;  // [L] x N_l
};

}  // namespace mrsim
