#include "contact/skin_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "contact/path_box.hpp"

namespace mrsim {

namespace {

constexpr int kSweepSamples = 16;  // tool poses per frame in the broad phase

double distance_to_segment(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double u = len2 > 0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (x - (a + u * ab)).norm();
}

}  // namespace

void ToolSampleBuffer::clear() {
  time.clear();
  position.clear();
  force.clear();
  orientation.clear();
  contacts.clear();
}

SkinContact::SkinContact(Skin skin, SkinBinding binding, std::vector<Tool> tools,
                         double p_wave_modulus)
    : skin_(std::move(skin)), binding_(std::move(binding)), tools_(std::move(tools)) {
  const std::size_t T = tools_.size();
  for (const Tool& tool : tools_)
    stiffness_.push_back(penalty_stiffness(skin_, tool, p_wave_modulus));
  penalty_ = skin_penalty(skin_, tools_, p_wave_modulus);
  candidates_.resize(T);
  vertex_force_.assign(skin_.rest.size(), Vec3::Zero());
  tool_force_.assign(T, Vec3::Zero());
  pose_.resize(T);
  max_depth_.assign(T, 0.0);
  contacts_.assign(T, 0);
  samples_.resize(T);
}

void SkinContact::remap(const Hierarchy& h,
                        const std::vector<const std::vector<std::uint8_t>*>& free_point) {
  map_.build(h, binding_, free_point);
  skin_version_ = 0;
}

// A skin vertex is near tool k over [t0, t1] when, at its current position x, it is within the
// tool's bounding ball (plus a margin for the skin's own motion) of the tool's path: the path is
// sampled, and the ball about the tool frame's origin contains the shape in any orientation.
void SkinContact::near_tool(int k, double t0, double t1, const std::vector<Vec3>& x,
                            double speed, std::vector<int>& out) const {
  const Tool& tool = tools_[k];
  const double reach = bounding_radius(tool.shape) * 1.05 + 2.0 * speed * (t1 - t0);
  std::array<Vec3, kSweepSamples + 1> path;
  for (int i = 0; i <= kSweepSamples; ++i)
    path[i] = tool.trajectory.pose(t0 + (t1 - t0) * i / kSweepSamples).position;
  // Sampling the path misses at most the chord of one interval: add the longest one.
  double chord = 0;
  for (int i = 1; i <= kSweepSamples; ++i) chord = std::max(chord, (path[i] - path[i - 1]).norm());
  const PathBox box(path);  // the vertices found are the same
  out.clear();
  for (int s = 0; s < static_cast<int>(x.size()); ++s) {
    if (box.beyond(x[s], reach + chord)) continue;
    double d = (x[s] - path[0]).norm();
    for (int i = 1; i <= kSweepSamples && d > reach + chord; ++i)
      d = std::min(d, distance_to_segment(x[s], path[i - 1], path[i]));
    if (d <= reach + chord) out.push_back(s);
  }
}

// The skin's positions and largest speed, once for all tools.
void SkinContact::near_tools(double t0, double t1, const std::vector<LevelFields>& fields,
                             std::vector<std::vector<int>>& out, std::uint64_t version) const {
  if (version == 0 || version != skin_version_) {
    const int n = map_.size();
    double speed = 0;
    skin_x_.resize(n);
    for (int s = 0; s < n; ++s) {
      Vec3 u, v;
      map_.interpolate(s, fields, u, v);
      skin_x_[s] = skin_.rest[s] + u;
      speed = std::max(speed, v.norm());
    }
    skin_speed_ = speed;
    skin_version_ = version;
  }
  out.resize(tools_.size());
  for (int k = 0; k < num_tools(); ++k) near_tool(k, t0, t1, skin_x_, skin_speed_, out[k]);
}

void SkinContact::begin_frame(double t0, double t1, const std::vector<LevelFields>& fields,
                              std::uint64_t version) {
  near_tools(t0, t1, fields, candidates_, version);
}

void SkinContact::restore_candidates(std::vector<std::vector<int>> candidates) {
  if (candidates.size() != tools_.size())
    throw std::invalid_argument("SkinContact::restore_candidates: " +
                                std::to_string(candidates.size()) + " tools, not " +
                                std::to_string(tools_.size()));
  const int n = static_cast<int>(skin_.rest.size());
  for (const std::vector<int>& c : candidates)
    for (int s : c)
      if (s < 0 || s >= n)
        throw std::invalid_argument("SkinContact::restore_candidates: skin vertex " +
                                    std::to_string(s) + " of " + std::to_string(n));
  candidates_ = std::move(candidates);
}

Vec3 SkinContact::penalty(int k, const ToolPose& pose, int s,
                          const std::vector<LevelFields>& fields, double& depth) const {
  const Tool& tool = tools_[k];
  const Vec3 x = skin_.rest[s] + map_.value(s, fields, false);
  const ShapeProbe probe_at = probe(tool.shape, pose.to_local(x));
  depth = probe_at.depth;
  if (depth <= 0) return Vec3::Zero();
  const Vec3 n = pose.orientation * probe_at.normal;
  const Vec3 relative = map_.value(s, fields, true) - pose.velocity_at(x);
  const double pressure = stiffness_[k][s] * depth - tool.contact.damping * relative.dot(n);
  return std::max(pressure, 0.0) * skin_.area[s] * n;
}

void SkinContact::touch(const std::vector<Vec3*>& external, const ActiveTerm& t, const Vec3& f,
                        Vec3& support) {
  if (t.level < 0) {
    support += t.weight * f;
    return;
  }
  external[t.level][t.point] += t.weight * f;
  touched_level_.push_back(t.level);
  touched_point_.push_back(t.point);
}

void SkinContact::clear(const std::vector<Vec3*>& external) {
  for (std::size_t i = 0; i < touched_level_.size(); ++i)
    external[touched_level_[i]][touched_point_[i]].setZero();
  touched_level_.clear();
  touched_point_.clear();
}

Vec3 SkinContact::apply(double t, const std::vector<LevelFields>& fields,
                        const std::vector<Vec3*>& external) {
  applied_at_ = t;
  for (int s : forced_) vertex_force_[s].setZero();
  forced_.clear();
  Vec3 support = Vec3::Zero();
  for (std::size_t k = 0; k < tools_.size(); ++k) {
    const ToolPose& pose = pose_[k] = tools_[k].trajectory.pose(t);
    tool_force_[k].setZero();
    max_depth_[k] = 0;
    contacts_[k] = 0;
    for (int s : candidates_[k]) {
      double depth = 0;
      const Vec3 f = penalty(static_cast<int>(k), pose, s, fields, depth);
      if (depth <= 0) continue;
      max_depth_[k] = std::max(max_depth_[k], depth);
      ++contacts_[k];
      if (vertex_force_[s].isZero()) forced_.push_back(s);
      vertex_force_[s] += f;
      tool_force_[k] -= f;
      for (const ActiveTerm& a : map_.row(s)) touch(external, a, f, support);
    }
  }
  return support;
}

void SkinContact::record_sample() {
  for (std::size_t k = 0; k < tools_.size(); ++k) {
    const ToolPose& pose = pose_[k];
    ToolSampleBuffer& b = samples_[k];
    b.time.push_back(applied_at_);
    b.position.push_back(pose.position);
    const Quat& q = pose.orientation;
    b.orientation.push_back({q.w(), q.x(), q.y(), q.z()});
    b.force.push_back(tool_force_[k]);
    b.contacts.push_back(contacts_[k]);
  }
}

void SkinContact::clear_samples() {
  for (ToolSampleBuffer& b : samples_) b.clear();
}

}  // namespace mrsim
