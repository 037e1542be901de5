#pragma once
// What the simulation hands to the writers for one display frame. Views only: the writers copy
// what they need, the simulation keeps ownership. Arrays are per point of one level.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

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
};

/// Per-frame scalars for `/frames/*` in log.h5. Vectors are indexed by level.
struct FrameRecord {
  int frame = 0;
  double time = 0;                 // s, simulated
  double kinetic_energy = 0;       // J
  double elastic_energy = 0;       // J
  double wall_time = 0;            // s, wall clock spent simulating this frame (0 at frame 0)
  Vec3 support_reaction = Vec3::Zero();  // N, force the fixed points exert on the body
  std::vector<std::int64_t> active;             // [L]
  std::vector<std::int64_t> ghosts;             // [L]
  std::vector<std::int64_t> force_evaluations;  // [L], cumulative point-force evaluations
  std::vector<std::int64_t> time_levels;             // [C] particles per time level
  std::vector<std::int64_t> time_level_evaluations;  // [C] cumulative, per time level
  std::vector<std::span<const std::int8_t>> status;  // [L] x N_l
};

}  // namespace mrsim
