#include "meshing/surface_mesh.hpp"

#include <Eigen/Geometry>
#include <map>
#include <tuple>

namespace mrsim {

double enclosed_volume(const SurfaceMesh& surface) {
  double six_volume = 0.0;
  for (const Triangle& t : surface.triangles) {
    const Vec3& a = surface.points[t[0]];
    six_volume += a.dot(surface.points[t[1]].cross(surface.points[t[2]]));
  }
  return six_volume / 6.0;
}

double triangle_area(const SurfaceMesh& surface, int triangle) {
  const Triangle& t = surface.triangles[triangle];
  const Vec3& a = surface.points[t[0]];
  return 0.5 * (surface.points[t[1]] - a).cross(surface.points[t[2]] - a).norm();
}

void scale_surface(SurfaceMesh& surface, double factor) {
  for (Vec3& p : surface.points) p *= factor;
}

int weld_identical_points(SurfaceMesh& surface) {
  // Exact comparison on purpose: merging "nearby" points would hide pinched vertices and
  // could glue distinct sheets together; CAD exporters write shared corners identically.
  using Key = std::tuple<double, double, double>;
  std::map<Key, int> index_of;
  std::vector<int> new_index(surface.points.size(), -1);
  std::vector<Vec3> kept;
  int used = 0;
  for (Triangle& t : surface.triangles) {
    for (int& v : t) {
      if (new_index[v] < 0) {
        const Vec3& p = surface.points[v];
        const auto [it, inserted] = index_of.try_emplace(Key{p.x(), p.y(), p.z()}, static_cast<int>(kept.size()));
        if (inserted) kept.push_back(p);
        new_index[v] = it->second;
        ++used;
      }
      v = new_index[v];
    }
  }
  const int merged = used - static_cast<int>(kept.size());
  surface.points = std::move(kept);
  return merged;
}

}  // namespace mrsim
