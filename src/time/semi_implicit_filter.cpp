#include "time/semi_implicit_filter.hpp"

#include <algorithm>

#include "core/parallel.hpp"
#include "physics/internal_force.hpp"

namespace mrsim {

std::vector<Mat3> point_jacobians(const LevelModel& model) {
  const int n = model.num_points();
  std::vector<Mat3> J(n);
  if (model.law.strain == StrainMeasure::Cauchy) {
    for (int i = 0; i < n; ++i) J[i] = -diagonal_block(model.K, model.adj, i);
    return J;
  }
  const double amplitude = 0.1 * *std::min_element(model.min_edge.begin(), model.min_edge.end());
  std::vector<Vec3> u(n, Vec3::Zero()), v(n, Vec3::Zero());
  // v = 0 during the probe, so the strain-rate damping does not enter J (elastic only).
  for (int i = 0; i < n; ++i) {
    const Vec3 f0 = Vec3::Zero();  // the rest state is force-free
    for (int k = 0; k < 3; ++k) {
      u[i] = Vec3::Zero();
      u[i][k] = amplitude;
      J[i].col(k) = (point_internal_force(model, i, u.data(), v.data()) - f0) / amplitude;
    }
    u[i] = Vec3::Zero();
  }
  return J;
}

SemiImplicitFilter::SemiImplicitFilter(const LevelModel& model)
    : jacobian_(point_jacobians(model)) {}

void SemiImplicitFilter::apply(PointState& s, IndexSet points, double dt) const {
  parallel_for(points.count, [&](int k) {
    const int i = points[k];
    if (!s.free_point[i]) return;
    const Mat3 W = (Mat3::Identity() - (dt * dt * s.inv_mass[i]) * jacobian_[i]).inverse();
    s.v[i] = W * s.v[i];
  });
}

}  // namespace mrsim
