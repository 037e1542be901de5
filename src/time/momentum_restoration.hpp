#pragma once
// Momentum restoration after the semi-implicit filter (method.md §5.3; the correction step of
// [DSB99]): eq. (5.1) makes each particle implicit against frozen neighbours, so it also brakes
// rigid motion. For a free body, the linear and angular momentum the filter removed is given
// back as a rigid velocity field a + ω × (x - c), which changes neither the elastic state nor
// the filter's damping of vibrations. Serial sums in a fixed order: thread-count independent.
#include <vector>

#include "core/index_set.hpp"
#include "time/point_state.hpp"

namespace mrsim {

/// Mass, first moment, linear and angular momentum (about the origin) of the free points, and
/// what their rotation from the rest shape is read from.
struct MomentumSums {
  double mass = 0;
  Vec3 moment = Vec3::Zero();       // Σ m x
  Vec3 linear = Vec3::Zero();       // Σ m v
  Vec3 angular = Vec3::Zero();      // Σ m x × v
  Mat3 inertia = Mat3::Zero();      // Σ m (|x|² I - x xᵀ), about the origin
  Vec3 rest_moment = Vec3::Zero();  // Σ m X
  Mat3 spread = Mat3::Zero();       // Σ m x Xᵀ
};

struct MomentumBlock {
  const PointState* state = nullptr;
  const Vec3* rest = nullptr;  // rest positions X (x = X + u)
  IndexSet points;
};

MomentumSums momentum_sums(const std::vector<MomentumBlock>& blocks);

/// The rigid velocity field a + ω × (x - c) with the linear and angular momentum of `sums`
/// (c its centre of mass): the body's rigid motion, which the filter must not brake.
struct RigidField {
  Vec3 a = Vec3::Zero(), omega = Vec3::Zero(), c = Vec3::Zero();
  Vec3 at(const Vec3& x) const { return a + omega.cross(x - c); }
};
RigidField rigid_field(const MomentumSums& sums);

/// The body's rotation from its rest shape: the rotation factor of the polar decomposition of
/// Σ m (x − c)(X − C)ᵀ (c, C the current and rest centres of mass), the best rigid fit of the
/// rest shape to the current one. The identity for an empty or degenerate body.
Mat3 body_rotation(const MomentumSums& sums);

/// v ← R v on the free points of `blocks`.
void rotate_velocities(const std::vector<MomentumBlock>& blocks, const Mat3& R,
                       std::vector<PointState*>& states);

/// v += sign × field(x) on the free points of `blocks`.
void add_rigid(const std::vector<MomentumBlock>& blocks, const RigidField& field, double sign,
               std::vector<PointState*>& states);

/// Adds a + ω × (x - c) to every free point so that the momenta equal `before` again.
void restore_momentum(const std::vector<MomentumBlock>& blocks, const MomentumSums& before,
                      std::vector<PointState*>& states);

/// The same when only part of the body was filtered (time levels: the particles kicked by one
/// sub-step): what `filtered` lost since `before` is given back as one rigid field over the
/// whole `body` (c and the inertia are the body's), so no velocity jump appears between the
/// filtered particles and the others.
void restore_momentum(const std::vector<MomentumBlock>& filtered, const MomentumSums& before,
                      const std::vector<MomentumBlock>& body, std::vector<PointState*>& states);

}  // namespace mrsim
