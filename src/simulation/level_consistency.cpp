#include "simulation/level_consistency.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <system_error>

#include "core/error.hpp"

namespace mrsim {

namespace {

struct Extent {
  double volume = 0;
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
};

Extent extent_of(const TetMesh& m) {
  Extent e;
  for (const Vec3& p : m.points) {
    e.lo = e.lo.cwiseMin(p);
    e.hi = e.hi.cwiseMax(p);
  }
  for (const Tet& t : m.tets)
    e.volume +=
        std::abs(signed_volume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]));
  return e;
}

std::string level(std::size_t k) { return "object.levels[" + std::to_string(k) + "]"; }

}  // namespace

void check_level_consistency(const Scenario& sc, const std::vector<const TetMesh*>& meshes) {
  const std::size_t n = meshes.size();
  for (std::size_t k = 1; k < n; ++k) {
    for (std::size_t j = 0; j < k; ++j) {
      std::error_code ec;
      if (std::filesystem::equivalent(sc.levels[j].mesh, sc.levels[k].mesh, ec))
        throw InputError(level(k) + ": the same mesh as " + level(j) + " (" +
                         sc.levels[k].mesh.string() + "); each level is its own mesh");
    }
    if (meshes[k]->tets.size() <= meshes[k - 1]->tets.size())
      throw InputError(level(k) + " has " + std::to_string(meshes[k]->tets.size()) +
                       " tets, not more than " + level(k - 1) + " (" +
                       std::to_string(meshes[k - 1]->tets.size()) +
                       "): list the levels coarse to fine");
  }
  const Extent fine = extent_of(*meshes.back());
  const double diagonal = (fine.hi - fine.lo).norm();
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const Extent e = extent_of(*meshes[k]);
    const double offset = (0.5 * (e.lo + e.hi) - 0.5 * (fine.lo + fine.hi)).norm();
    if (std::abs(e.volume / fine.volume - 1.0) > 0.25 || offset > 0.25 * diagonal) {
      std::ostringstream os;
      os << level(k) << " is not the object of the finest level " << level(n - 1) << ": volume "
         << e.volume << " m^3 against " << fine.volume << " m^3, bounding-box centres " << offset
         << " m apart (box diagonal " << diagonal
         << " m); every level must mesh the same object (at most 25 % apart)";
      throw InputError(os.str());
    }
  }
}

}  // namespace mrsim
