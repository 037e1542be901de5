#include "time/semi_implicit_filter.hpp"

#include <stdexcept>

#include "core/parallel.hpp"
#include "physics/edge_operators.hpp"

namespace mrsim {

std::vector<Mat3> point_jacobians(const LevelModel& model) {
  const int n = model.num_points();
  if (n > 0 && model.K.empty())
    throw std::logic_error("point_jacobians: the level was built without its edge matrices");
  std::vector<Mat3> J(n);
  for (int i = 0; i < n; ++i) J[i] = -diagonal_block(model.K, model.adj, i);
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
