#pragma once
// Garland & Heckbert's quadric error metric (the "Q" of qslim): the sum, over a set of planes,
// of the area-weighted squared distance of a point to each plane. A vertex starts with the
// planes of its triangles; an edge collapse adds the two quadrics, so the error of a point
// measures how far it lies from every input triangle the collapsed region came from.
#include <Eigen/Dense>

#include "core/vec.hpp"

namespace mrsim {

class Quadric {
 public:
  /// The plane through a, b, c, weighted by the triangle's area (zero for a degenerate one).
  static Quadric of_triangle(const Vec3& a, const Vec3& b, const Vec3& c);

  Quadric& operator+=(const Quadric& other);
  friend Quadric operator+(Quadric a, const Quadric& b) { return a += b; }

  /// Mean squared distance (m^2) of p to the planes: area-weighted sum over total area.
  double mean_squared_distance(const Vec3& p) const;

  /// The point minimising the error, searched from `anchor`: directions in which the error
  /// is (nearly) flat, such as along a plane or a cylinder's axis, keep the anchor's
  /// coordinate, so flat regions collapse to edge midpoints and keep their triangles' shape.
  Vec3 best_point(const Vec3& anchor) const;

 private:
  Eigen::Matrix4d q_ = Eigen::Matrix4d::Zero();
  double area_ = 0.0;
};

}  // namespace mrsim
