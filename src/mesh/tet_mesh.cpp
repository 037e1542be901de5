#include "mesh/tet_mesh.hpp"

// cross() is declared by Eigen/Core but defined in Eigen/Geometry: without it, a link error.
#include <Eigen/Geometry>

namespace mrsim {
double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

double bbox_diagonal(const TetMesh& mesh) {
  Vec3 lo = mesh.points.front(), hi = lo;
  for (const Vec3& p : mesh.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}
}  // namespace mrsim
