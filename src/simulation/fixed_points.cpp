#include "simulation/fixed_points.hpp"

#include <string>

#include "core/error.hpp"
#include "core/log.hpp"

namespace mrsim {

namespace {

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

int mark_region(const TetMesh& mesh, const FixedRegion& r, size_t index,
                std::vector<std::uint8_t>& mask) {
  if (r.kind == FixedRegion::Kind::Ids) {
    for (int id : r.ids) {
      if (id < 0 || id >= static_cast<int>(mesh.points.size()))
        throw InputError("fixed[" + std::to_string(index) + "].ids: vertex id " +
                         std::to_string(id) + " is out of range (the mesh has " +
                         std::to_string(mesh.points.size()) + " vertices)");
      mask[id] = 1;
    }
    return static_cast<int>(r.ids.size());
  }
  const double tol = 1e-9 * bbox_diagonal(mesh);
  int count = 0;
  for (size_t i = 0; i < mesh.points.size(); ++i)
    if (selects(r, mesh.points[i], tol)) {
      mask[i] = 1;
      ++count;
    }
  return count;
}

}  // namespace

std::vector<std::vector<std::uint8_t>> select_fixed_points(
    const std::vector<const TetMesh*>& levels, const std::vector<FixedRegion>& regions) {
  std::vector<std::vector<std::uint8_t>> masks(levels.size());
  for (size_t l = 0; l < levels.size(); ++l) masks[l].assign(levels[l]->points.size(), 0);
  for (size_t k = 0; k < regions.size(); ++k) {
    int total = 0;
    for (size_t l = 0; l < levels.size(); ++l) {
      if (regions[k].level >= 0 && regions[k].level != static_cast<int>(l)) continue;
      const int n = mark_region(*levels[l], regions[k], k, masks[l]);
      if (n == 0 && levels.size() > 1)
        warn("fixed[" + std::to_string(k) + "] selects no vertex of level " + std::to_string(l));
      total += n;
    }
    if (total == 0)
      throw InputError("fixed[" + std::to_string(k) +
                       "]: selects no vertex of the mesh (coordinates are in metres, after the "
                       "unit conversion of object.units)");
  }
  return masks;
}

}  // namespace mrsim
