#include "time/momentum_restoration.hpp"

namespace mrsim {

MomentumSums momentum_sums(const std::vector<MomentumBlock>& blocks) {
  MomentumSums s;
  for (const MomentumBlock& b : blocks)
    for (int k = 0; k < b.points.count; ++k) {
      const int i = b.points[k];
      if (!b.state->free_point[i]) continue;
      const double m = 1.0 / b.state->inv_mass[i];
      const Vec3 x = b.rest[i] + b.state->u[i];
      s.mass += m;
      s.moment += m * x;
      s.linear += m * b.state->v[i];
      s.angular += m * x.cross(b.state->v[i]);
      s.inertia += m * (x.squaredNorm() * Mat3::Identity() - x * x.transpose());
    }
  return s;
}

void restore_momentum(const std::vector<MomentumBlock>& blocks, const MomentumSums& before,
                      std::vector<PointState*>& states) {
  const MomentumSums after = momentum_sums(blocks);
  if (after.mass <= 0) return;
  const Vec3 c = after.moment / after.mass;
  const Vec3 a = (before.linear - after.linear) / after.mass;
  // Inertia about c (parallel axis), and the angular momentum still missing once a is added.
  const Mat3 inertia_c =
      after.inertia - after.mass * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
  const Vec3 missing = before.angular - after.angular - after.mass * c.cross(a);
  const Vec3 omega = inertia_c.ldlt().solve(missing);
  for (size_t k = 0; k < blocks.size(); ++k) {
    const MomentumBlock& b = blocks[k];
    PointState& s = *states[k];
    for (int j = 0; j < b.points.count; ++j) {
      const int i = b.points[j];
      if (s.free_point[i]) s.v[i] += a + omega.cross(b.rest[i] + s.u[i] - c);
    }
  }
}

}  // namespace mrsim
