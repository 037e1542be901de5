#include "simulation/surface_load_distribution.hpp"

#include <cmath>

#include <map>
#include <string>

#include "core/error.hpp"
#include "mesh/boundary_faces.hpp"

namespace mrsim {

namespace {

struct FaceRef {
  Vec3 centroid;
  double area;
  Face face;
};

std::vector<FaceRef> faces_of(const TetMesh& mesh) {
  std::vector<FaceRef> out;
  for (const Face& f : boundary_faces(mesh)) {
    const Vec3 &a = mesh.points[f[0]], &b = mesh.points[f[1]], &c = mesh.points[f[2]];
    out.push_back({(a + b + c) / 3.0, 0.5 * (b - a).cross(c - a).norm(), f});
  }
  return out;
}

// Distance from x to the box (0 inside).
double box_distance(const Vec3& x, const SurfaceLoadSpec& s) {
  return (x - x.cwiseMax(s.min).cwiseMin(s.max)).norm();
}

NodalLoad spread(const std::vector<const FaceRef*>& faces, const Vec3& force) {
  double area = 0;
  for (const FaceRef* f : faces) area += f->area;
  std::map<int, Vec3> nodal;  // ordered: deterministic point order
  for (const FaceRef* f : faces)
    for (int v : f->face) {
      auto [it, fresh] = nodal.try_emplace(v, Vec3::Zero());
      it->second += force * (f->area / (3.0 * area));
    }
  NodalLoad load;
  for (const auto& [p, f] : nodal) {
    load.points.push_back(p);
    load.force.push_back(f);
  }
  return load;
}

}  // namespace

SurfaceLoad distribute_surface_load(const TetMesh& finest, const SurfaceLoadSpec& spec,
                                    std::size_t index) {
  const std::vector<FaceRef> faces = faces_of(finest);
  const double tol = 1e-9 * std::sqrt(faces.empty() ? 1.0 : faces.front().area);
  std::vector<const FaceRef*> chosen;
  for (const FaceRef& f : faces)
    if (box_distance(f.centroid, spec) <= tol) chosen.push_back(&f);
  if (chosen.empty())
    throw InputError("loads[" + std::to_string(index) +
                     "].box: no boundary face of the finest level has its centroid in the box "
                     "(coordinates are in metres, after the unit conversion of object.units)");
  return {spread(chosen, spec.force), spec.profile};
}

}  // namespace mrsim
