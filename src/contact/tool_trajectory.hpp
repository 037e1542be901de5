#pragma once
// How a tool moves (scenario `tools[].trajectory`): keyframes (time, position, optional
// orientation) interpolated linearly or smoothly, or samples recorded from a device (CSV).
// Before the first time the pose is the first one, after the last time the last one.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/vec.hpp"

namespace mrsim {

using Quat = Eigen::Quaterniond;

enum class Interpolation {
  Linear,  // piecewise-linear positions, slerp orientations
  Smooth   // C1: cubic Hermite positions with Catmull–Rom tangents for uneven times (zero
           // velocity at the first and last keyframes), slerp orientations eased the same way
};

struct Keyframe {
  double t = 0;  // s, strictly increasing along a trajectory
  Vec3 position = Vec3::Zero();                 // m, world frame
  Quat orientation = Quat::Identity();          // tool frame -> world frame, unit
};

struct ToolPose {
  Vec3 position = Vec3::Zero();
  Quat orientation = Quat::Identity();
  Vec3 velocity = Vec3::Zero();          // m/s, of the tool frame's origin
  Vec3 angular_velocity = Vec3::Zero();  // rad/s, world frame
  /// World coordinates of a point given in the tool frame, and back.
  Vec3 to_world(const Vec3& local) const { return position + orientation * local; }
  Vec3 to_local(const Vec3& world) const { return orientation.conjugate() * (world - position); }
  /// Velocity of the tool's material point at world position x.
  Vec3 velocity_at(const Vec3& x) const { return velocity + angular_velocity.cross(x - position); }
};

class ToolTrajectory {
 public:
  ToolTrajectory() = default;
  /// At least one keyframe, strictly increasing times, unit quaternions (normalised here;
  /// throws InputError naming `what` otherwise). Consecutive quaternions are flipped to the
  /// same hemisphere so slerp takes the short way.
  ToolTrajectory(std::vector<Keyframe> keys, Interpolation interpolation, const std::string& what);

  /// Pose and velocities at time t (s). No allocation.
  ToolPose pose(double t) const;
  const std::vector<Keyframe>& keys() const { return keys_; }
  Interpolation interpolation() const { return interpolation_; }

 private:
  ToolPose linear(std::size_t k, double t) const;  // t inside segment k..k+1
  ToolPose smooth(std::size_t k, double t) const;
  Vec3 tangent(std::size_t k) const;  // Catmull–Rom velocity at key k (zero at both ends)

  std::vector<Keyframe> keys_;
  Interpolation interpolation_ = Interpolation::Linear;
};

/// A device recording: one sample per line, `t, x, y, z` or `t, x, y, z, qw, qx, qy, qz`
/// (metres, seconds; quaternion tool -> world), comma or whitespace separated; an optional
/// header line whose first field is not a number; `#` comments and blank lines ignored.
/// Throws InputError with the file, line and reason on a malformed line, a non-finite value,
/// times not strictly increasing, a zero quaternion, mixed column counts, or no sample.
std::vector<Keyframe> read_trajectory_csv(const std::filesystem::path& file);

}  // namespace mrsim
