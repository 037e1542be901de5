#include "contact/tool_trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/portable_math.hpp"
#include "core/error.hpp"

namespace mrsim {

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& reason) {
  std::ostringstream msg;
  msg << what << ": " << reason;
  throw InputError(msg.str());
}

std::string keyframe_label(std::size_t k) {
  std::ostringstream s;
  s << "keyframe " << k;
  return s.str();
}

// Validates one keyframe and makes its quaternion unit.
void check_keyframe(Keyframe& key, std::size_t k, const std::string& what) {
  if (!std::isfinite(key.t)) fail(what, keyframe_label(k) + ": time is not finite");
  if (!key.position.allFinite()) fail(what, keyframe_label(k) + ": position is not finite");
  if (!key.orientation.coeffs().allFinite())
    fail(what, keyframe_label(k) + ": orientation is not finite");
  const double norm = key.orientation.norm();
  if (norm < 1e-12) fail(what, keyframe_label(k) + ": orientation quaternion is zero");
  key.orientation.coeffs() /= norm;
}

void check_after(const Keyframe& prev, const Keyframe& key, std::size_t k,
                 const std::string& what) {
  if (key.t > prev.t) return;
  std::ostringstream s;
  s << std::setprecision(12) << "keyframe " << k << " time " << key.t << " s is not after "
    << prev.t << " s";
  fail(what, s.str());
}

// Rotation vector (axis * angle) of a unit quaternion with w >= 0, so |angle| <= pi.
Vec3 rotation_vector(const Quat& q) {
  const double s = q.vec().norm();
  if (s < 1e-300) return Vec3::Zero();
  return q.vec() * (2.0 * portable::atan2(s, q.w()) / s);
}

Quat from_rotation_vector(const Vec3& v) {
  const double angle = v.norm();
  // sin(angle/2)/angle -> 1/2 as the angle vanishes; the series keeps full precision there.
  const double k = angle < 1e-8 ? 0.5 - angle * angle / 48.0 : portable::sin(0.5 * angle) / angle;
  const Vec3 xyz = k * v;
  return Quat(portable::cos(0.5 * angle), xyz.x(), xyz.y(), xyz.z());
}

ToolPose at_key(const Keyframe& key) {
  ToolPose pose;
  pose.position = key.position;
  pose.orientation = key.orientation;
  return pose;
}

// Orientation along a segment: q(s) = exp(s * w) * q0 with w the relative rotation in the
// world frame, so the angular velocity is w * ds/dt exactly.
void orient(const Keyframe& a, const Keyframe& b, double s, double ds_dt, ToolPose& pose) {
  const Vec3 w = rotation_vector(b.orientation * a.orientation.conjugate());
  pose.orientation = (from_rotation_vector(s * w) * a.orientation).normalized();
  pose.angular_velocity = w * ds_dt;
}

}  // namespace

ToolTrajectory::ToolTrajectory(std::vector<Keyframe> keys, Interpolation interpolation,
                               const std::string& what)
    : keys_(std::move(keys)), interpolation_(interpolation) {
  if (keys_.empty()) fail(what, "no keyframe");
  for (std::size_t k = 0; k < keys_.size(); ++k) {
    check_keyframe(keys_[k], k, what);
    if (k == 0) continue;
    check_after(keys_[k - 1], keys_[k], k, what);
    // Same hemisphere as the previous key: slerp then takes the short way.
    if (keys_[k].orientation.dot(keys_[k - 1].orientation) < 0)
      keys_[k].orientation.coeffs() *= -1.0;
  }
}

Vec3 ToolTrajectory::tangent(std::size_t k) const {
  if (k == 0 || k + 1 >= keys_.size()) return Vec3::Zero();  // the tool starts and stops at rest
  const Keyframe& prev = keys_[k - 1];
  const Keyframe& next = keys_[k + 1];
  return (next.position - prev.position) / (next.t - prev.t);
}

ToolPose ToolTrajectory::pose(double t) const {
  // `!(t > t0)` also sends a NaN time to the first pose instead of through the search.
  if (!(t > keys_.front().t)) return at_key(keys_.front());
  if (t >= keys_.back().t) return at_key(keys_.back());
  const auto before = [](double time, const Keyframe& key) { return time < key.t; };
  const auto after = std::upper_bound(keys_.begin(), keys_.end(), t, before);
  const std::size_t k = static_cast<std::size_t>(after - keys_.begin()) - 1;
  return interpolation_ == Interpolation::Linear ? linear(k, t) : smooth(k, t);
}

ToolPose ToolTrajectory::linear(std::size_t k, double t) const {
  const Keyframe& a = keys_[k];
  const Keyframe& b = keys_[k + 1];
  const double h = b.t - a.t;
  const double u = (t - a.t) / h;
  ToolPose pose;
  pose.position = (1 - u) * a.position + u * b.position;
  pose.velocity = (b.position - a.position) / h;
  orient(a, b, u, 1.0 / h, pose);
  return pose;
}

ToolPose ToolTrajectory::smooth(std::size_t k, double t) const {
  const Keyframe& a = keys_[k];
  const Keyframe& b = keys_[k + 1];
  const double h = b.t - a.t;
  const double u = (t - a.t) / h;
  const double u2 = u * u, u3 = u2 * u;
  // Cubic Hermite basis and its derivative in u; tangents are per second, hence the h.
  const Vec3 ma = h * tangent(k), mb = h * tangent(k + 1);
  const Vec3 dp = b.position - a.position;
  ToolPose pose;
  pose.position = a.position + (3 * u2 - 2 * u3) * dp + (u3 - 2 * u2 + u) * ma + (u3 - u2) * mb;
  pose.velocity = ((6 * u - 6 * u2) * dp + (3 * u2 - 4 * u + 1) * ma + (3 * u2 - 2 * u) * mb) / h;
  orient(a, b, 3 * u2 - 2 * u3, (6 * u - 6 * u2) / h, pose);
  return pose;
}

}  // namespace mrsim
