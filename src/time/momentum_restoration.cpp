#include "time/momentum_restoration.hpp"

#include <Eigen/SVD>

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
      s.rest_moment += m * b.rest[i];
      s.spread += m * x * b.rest[i].transpose();
    }
  return s;
}

namespace {

// visit(rest, state, i) for every free point i of `blocks` (states[k] is block k's state).
template <class Visit>
void for_each_free_point(const std::vector<MomentumBlock>& blocks,
                         std::vector<PointState*>& states, Visit&& visit) {
  for (size_t k = 0; k < blocks.size(); ++k) {
    const MomentumBlock& b = blocks[k];
    PointState& s = *states[k];
    for (int j = 0; j < b.points.count; ++j) {
      const int i = b.points[j];
      if (s.free_point[i]) visit(b.rest, s, i);
    }
  }
}

// The rigid field a + ω × (x - c) over a body of the given mass, moment and inertia (about the
// origin) whose linear momentum is `linear` and angular momentum about the origin `angular`.
RigidField field_of(const MomentumSums& body, const Vec3& linear, const Vec3& angular) {
  RigidField r;
  if (body.mass <= 0) return r;
  r.c = body.moment / body.mass;
  r.a = linear / body.mass;
  // Inertia about c (parallel axis), and the angular momentum left once a is accounted for.
  const Mat3 inertia_c =
      body.inertia - body.mass * (r.c.squaredNorm() * Mat3::Identity() - r.c * r.c.transpose());
  r.omega = inertia_c.ldlt().solve(angular - body.mass * r.c.cross(r.a));
  return r;
}

// Adds to `blocks` (whose mass, moment and inertia are `body`) the rigid field that carries the
// linear and angular momentum `lost`.
void give_back(const MomentumSums& lost, const MomentumSums& body,
               const std::vector<MomentumBlock>& blocks, std::vector<PointState*>& states) {
  if (body.mass <= 0) return;
  add_rigid(blocks, field_of(body, lost.linear, lost.angular), 1.0, states);
}

MomentumSums lost_since(const MomentumSums& before, const MomentumSums& after) {
  MomentumSums lost;
  lost.linear = before.linear - after.linear;
  lost.angular = before.angular - after.angular;
  return lost;
}

}  // namespace

RigidField rigid_field(const MomentumSums& sums) {
  return field_of(sums, sums.linear, sums.angular);
}

Mat3 body_rotation(const MomentumSums& sums) {
  if (sums.mass <= 0) return Mat3::Identity();
  const Mat3 a = sums.spread - sums.moment * sums.rest_moment.transpose() / sums.mass;
  const Eigen::JacobiSVD<Mat3> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  if (!(svd.singularValues()[0] > 0)) return Mat3::Identity();
  Mat3 u = svd.matrixU();
  if ((u * svd.matrixV().transpose()).determinant() < 0) u.col(2) *= -1;  // no reflection
  return u * svd.matrixV().transpose();
}

void rotate_velocities(const std::vector<MomentumBlock>& blocks, const Mat3& R,
                       std::vector<PointState*>& states) {
  for_each_free_point(blocks, states, [&](const Vec3*, PointState& s, int i) {
    s.v[i] = R * s.v[i];
  });
}

void add_rigid(const std::vector<MomentumBlock>& blocks, const RigidField& field, double sign,
               std::vector<PointState*>& states) {
  for_each_free_point(blocks, states, [&](const Vec3* rest, PointState& s, int i) {
    s.v[i] += sign * field.at(rest[i] + s.u[i]);
  });
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
