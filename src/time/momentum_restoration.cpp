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

namespace {

// Adds to `blocks` (whose mass, moment and inertia are `body`) the rigid field that carries the
// linear and angular momentum `lost`.
void give_back(const MomentumSums& lost, const MomentumSums& body,
               const std::vector<MomentumBlock>& blocks, std::vector<PointState*>& states) {
  if (body.mass <= 0) return;
  const Vec3 c = body.moment / body.mass;
  const Vec3 a = lost.linear / body.mass;
  // Inertia about c (parallel axis), and the angular momentum still missing once a is added.
  const Mat3 inertia_c =
      body.inertia - body.mass * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
  const Vec3 missing = lost.angular - body.mass * c.cross(a);
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

MomentumSums lost_since(const MomentumSums& before, const MomentumSums& after) {
  MomentumSums lost;
  lost.linear = before.linear - after.linear;
  lost.angular = before.angular - after.angular;
  return lost;
}

}  // namespace

RigidField rigid_field(const MomentumSums& sums) {
  RigidField r;
  if (sums.mass <= 0) return r;
  r.c = sums.moment / sums.mass;
  r.a = sums.linear / sums.mass;
  const Mat3 inertia_c =
      sums.inertia - sums.mass * (r.c.squaredNorm() * Mat3::Identity() - r.c * r.c.transpose());
  r.omega = inertia_c.ldlt().solve(sums.angular - r.c.cross(sums.linear));
  return r;
}

void add_rigid(const std::vector<MomentumBlock>& blocks, const RigidField& field, double sign,
               std::vector<PointState*>& states) {
  for (size_t k = 0; k < blocks.size(); ++k) {
    const MomentumBlock& b = blocks[k];
    PointState& s = *states[k];
    for (int j = 0; j < b.points.count; ++j) {
      const int i = b.points[j];
      if (s.free_point[i]) s.v[i] += sign * field.at(b.rest[i] + s.u[i]);
    }
  }
}

void restore_momentum(const std::vector<MomentumBlock>& blocks, const MomentumSums& before,
                      std::vector<PointState*>& states) {
  const MomentumSums after = momentum_sums(blocks);
  give_back(lost_since(before, after), after, blocks, states);
}

void restore_momentum(const std::vector<MomentumBlock>& filtered, const MomentumSums& before,
                      const std::vector<MomentumBlock>& body, std::vector<PointState*>& states) {
  give_back(lost_since(before, momentum_sums(filtered)), momentum_sums(body), body, states);
}

}  // namespace mrsim
