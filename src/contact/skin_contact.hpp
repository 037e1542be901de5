#pragma once
// Tools against the object's skin (method.md §6.2): the broad phase once per display frame
// (skin vertices that can reach a tool during the frame), the penalty response at every
// simulation step on those candidates, the forces carried to the active points through the
// skin map, and the haptic-rate samples of every tool (pose, force, contacts).
#include <array>
#include <cstdint>
#include <vector>

#include "contact/contact_bound.hpp"
#include "contact/skin.hpp"
#include "contact/skin_binding.hpp"
#include "contact/skin_map.hpp"
#include "contact/tool.hpp"

namespace mrsim {

/// The longest interval between two samples of the tool force (s): a haptic device wants its
/// force at 1 kHz (thesis §5.1). With time levels, ticks where nobody is kicked are still
/// visited at this rate to move the skin and sample the force.
inline constexpr double kHapticPeriod = 1e-3;

/// What one tool did at every step of the current frame (struct of arrays, log.h5 /tool*).
struct ToolSampleBuffer {
  std::vector<double> time;
  std::vector<Vec3> position, force;
  std::vector<std::array<double, 4>> orientation;  // w, x, y, z
  std::vector<std::int32_t> contacts;
  void clear();
};

class SkinContact {
 public:
  /// `p_wave_modulus` (λ + 2μ, Pa) sets the automatic stiffness of a tool whose law has none:
  /// (λ + 2μ) / h at a skin vertex whose edges have mean length h, about the P-wave stiffness
  /// of the skin element, which the Courant step of the finest level tolerates.
  SkinContact(Skin skin, SkinBinding binding, std::vector<Tool> tools, double p_wave_modulus);

  /// After every topology change (which active points move the skin).
  void remap(const Hierarchy& h, const std::vector<const std::vector<std::uint8_t>*>& free_point);
  /// Broad phase for the frame [t0, t1] at the current state (`version`: see near_tools()).
  void begin_frame(double t0, double t1, const std::vector<LevelFields>& fields,
                   std::uint64_t version = 0);
  /// For every tool k, the skin vertices it may reach during [t0, t1] (out[k], sorted;
  /// O(skin vertices × tools)). `version` names the state of `fields` (0: none): a call with
  /// the version of the last one reuses its skin positions and speed instead of interpolating
  /// them again (the refinement's look-ahead and the next frame's broad phase see the same
  /// state when no step or topology change comes between them).
  void near_tools(double t0, double t1, const std::vector<LevelFields>& fields,
                  std::vector<std::vector<int>>& out, std::uint64_t version = 0) const;
  /// Removes the forces of the last apply() from `external` (per level, N).
  void clear(const std::vector<Vec3*>& external);
  /// Contact forces at time t for the current state, added to the active points' `external`
  /// (call clear() first); what reaches fixed points is returned (the support's share).
  /// O(candidates × row length), no allocation once the lists have grown.
  Vec3 apply(double t, const std::vector<LevelFields>& fields, const std::vector<Vec3*>& external);
  /// Appends one sample per tool: the time, pose and forces of the last apply().
  void record_sample();

  int num_tools() const { return static_cast<int>(tools_.size()); }
  const Tool& tool(int k) const { return tools_[k]; }
  const ToolSampleBuffer& samples(int k) const { return samples_[k]; }
  void clear_samples();
  /// Force the object exerts on tool k at the last apply() (N).
  const Vec3& tool_force(int k) const { return tool_force_[k]; }
  /// Largest depth of a skin vertex inside tool k at the last apply() (m, 0 when none).
  double max_depth(int k) const { return max_depth_[k]; }

  const Skin& skin() const { return skin_; }
  const SkinMap& map() const { return map_; }
  /// Per tool, the skin vertices of the frame's broad phase (sorted).
  const std::vector<std::vector<int>>& candidates() const { return candidates_; }
  /// A checkpoint's broad phase (per tool, sorted skin vertices), as begin_frame() left it;
  /// throws std::invalid_argument on a tool count or vertex out of range.
  void restore_candidates(std::vector<std::vector<int>> candidates);
  /// The penalty of every skin vertex (largest over the tools), for the stable step.
  const SkinPenalty& penalty() const { return penalty_; }
  /// Contact force on each skin vertex at the last apply() (N).
  const std::vector<Vec3>& vertex_force() const { return vertex_force_; }

 private:
  void touch(const std::vector<Vec3*>& external, const ActiveTerm& t, const Vec3& f, Vec3& support);
  void near_tool(int k, double t0, double t1, const std::vector<Vec3>& x, double speed,
                 std::vector<int>& out) const;
  Vec3 penalty(int k, const ToolPose& pose, int s, const std::vector<LevelFields>& fields,
               double& depth) const;

  Skin skin_;
  SkinBinding binding_;
  SkinMap map_;
  std::vector<Tool> tools_;
  std::vector<std::vector<double>> stiffness_;  // per tool, per skin vertex (Pa/m)
  SkinPenalty penalty_;
  std::vector<std::vector<int>> candidates_;  // per tool, skin vertices
  // The skin's positions and largest speed at state skin_version_ (0: none; remap() drops them).
  mutable std::vector<Vec3> skin_x_;
  mutable double skin_speed_ = 0;
  mutable std::uint64_t skin_version_ = 0;
  std::vector<int> touched_level_, touched_point_;  // where the last forces went
  std::vector<int> forced_;                          // skin vertices with a force
  std::vector<Vec3> vertex_force_;
  std::vector<Vec3> tool_force_;
  std::vector<ToolPose> pose_;  // per tool, at the last apply()
  double applied_at_ = 0;       // time of the last apply() (s)
  std::vector<double> max_depth_;
  std::vector<std::int32_t> contacts_;
  std::vector<ToolSampleBuffer> samples_;
};

}  // namespace mrsim
