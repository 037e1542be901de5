#include "meshing/quadric.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>

namespace mrsim {
namespace {

// Eigenvalues of the quadric's 3x3 part below this fraction of the largest are treated as
// flat: solving along them would move points far along nearly-flat valleys.
constexpr double kFlatEigenvalue = 1e-3;

}  // namespace

Quadric Quadric::of_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  Quadric quadric;
  const Vec3 cross = (b - a).cross(c - a);
  const double twice_area = cross.norm();
  if (twice_area == 0.0) return quadric;
  const Vec3 n = cross / twice_area;
  const Eigen::Vector4d plane(n.x(), n.y(), n.z(), -n.dot(a));
  quadric.area_ = 0.5 * twice_area;
  quadric.q_ = quadric.area_ * plane * plane.transpose();
  return quadric;
}

Quadric& Quadric::operator+=(const Quadric& other) {
  q_ += other.q_;
  area_ += other.area_;
  return *this;
}

double Quadric::mean_squared_distance(const Vec3& p) const {
  if (area_ == 0.0) return 0.0;
  const Eigen::Vector4d h(p.x(), p.y(), p.z(), 1.0);
  return std::max(0.0, h.dot(q_ * h)) / area_;
}

Vec3 Quadric::best_point(const Vec3& anchor) const {
  // Minimise x^T A x + 2 b^T x + c around the anchor with a truncated pseudo-inverse of A.
  const Mat3 a = q_.topLeftCorner<3, 3>();
  const Vec3 b = q_.topRightCorner<3, 1>();
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(a);
  const Vec3 gradient = a * anchor + b;
  const double largest = eigen.eigenvalues().cwiseAbs().maxCoeff();
  if (largest == 0.0) return anchor;
  Vec3 step = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    const double lambda = eigen.eigenvalues()[k];
    if (lambda <= kFlatEigenvalue * largest) continue;
    const Vec3 axis = eigen.eigenvectors().col(k);
    step -= axis * (axis.dot(gradient) / lambda);
  }
  return anchor + step;
}

}  // namespace mrsim
