#include "simulation/fixed_points.hpp"

#include <string>

#include "core/error.hpp"

namespace mrsim {

namespace {

double bbox_diagonal(const TetMesh& mesh) {
  Vec3 lo = mesh.points.front(), hi = lo;
  for (const Vec3& p : mesh.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

bool selects(const FixedRegion& r, const Vec3& X, double tol) {
  switch (r.kind) {
    case FixedRegion::Kind::Box:
      return (X.array() >= r.min.array() - tol).all() && (X.array() <= r.max.array() + tol).all();
    case FixedRegion::Kind::HalfSpace:
      return (X - r.point).dot(r.normal.normalized()) >= -tol;
    case FixedRegion::Kind::Ids:
      return false;
  }
  return false;
}

int mark_region(const TetMesh& mesh, const FixedRegion& r, double tol, size_t index,
                std::vector<std::uint8_t>& mask) {
  int count = 0;
  if (r.kind == FixedRegion::Kind::Ids) {
    for (int id : r.ids) {
      if (id < 0 || id >= static_cast<int>(mesh.points.size()))
        throw InputError("fixed[" + std::to_string(index) + "].ids: vertex id " +
                         std::to_string(id) + " is out of range (the mesh has " +
                         std::to_string(mesh.points.size()) + " vertices)");
      count += mask[id] == 0;
      mask[id] = 1;
    }
    return static_cast<int>(r.ids.size());
  }
  for (size_t i = 0; i < mesh.points.size(); ++i)
    if (selects(r, mesh.points[i], tol)) {
      mask[i] = 1;
      ++count;
    }
  return count;
}

}  // namespace

std::vector<std::uint8_t> select_fixed_points(const TetMesh& mesh,
                                              const std::vector<FixedRegion>& regions) {
  std::vector<std::uint8_t> mask(mesh.points.size(), 0);
  if (mesh.points.empty()) return mask;
  const double tol = 1e-9 * bbox_diagonal(mesh);
  for (size_t k = 0; k < regions.size(); ++k)
    if (mark_region(mesh, regions[k], tol, k, mask) == 0)
      throw InputError("fixed[" + std::to_string(k) +
                       "]: selects no vertex of the mesh (coordinates are in metres, after the "
                       "unit conversion of object.units)");
  return mask;
}

}  // namespace mrsim
