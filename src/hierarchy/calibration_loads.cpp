#include "hierarchy/calibration_loads.hpp"

#include <algorithm>
#include <limits>

#include "hierarchy/tet_locator.hpp"
#include "mesh/boundary_faces.hpp"

namespace mrsim {

std::vector<LocalLoad> local_loads(const TetMesh& finest, const std::vector<std::uint8_t>& fixed,
                                   int count, double radius) {
  // Area-weighted outward normals of the free boundary points.
  std::vector<Vec3> normal(finest.points.size(), Vec3::Zero());
  for (const Face& f : boundary_faces(finest)) {
    const Vec3& a = finest.points[f[0]];
    const Vec3 n = (finest.points[f[1]] - a).cross(finest.points[f[2]] - a);
    for (int v : f) normal[v] += n;
  }
  std::vector<int> free;
  for (std::size_t i = 0; i < normal.size(); ++i)
    if (normal[i].squaredNorm() > 0 && (fixed.empty() || !fixed[i])) free.push_back(static_cast<int>(i));
  std::vector<LocalLoad> loads;
  if (free.empty()) return loads;
  // Farthest-point sampling from the highest point: spread over the surface, deterministic.
  std::vector<double> gap(free.size(), std::numeric_limits<double>::infinity());
  int next = *std::max_element(free.begin(), free.end(), [&](int a, int b) {
    return finest.points[a].z() < finest.points[b].z() || (finest.points[a].z() == finest.points[b].z() && a > b);
  });
  for (int k = 0; k < count && k < static_cast<int>(free.size()); ++k) {
    const Vec3& c = finest.points[next];
    LocalLoad load;
    for (int i : free)
      if ((finest.points[i] - c).norm() <= radius) load.points.push_back(i);
    load.force = -normal[next].normalized() / static_cast<double>(load.points.size());
    loads.push_back(std::move(load));
    std::size_t far = 0;
    for (std::size_t j = 0; j < free.size(); ++j) {
      gap[j] = std::min(gap[j], (finest.points[free[j]] - c).norm());
      if (gap[j] > gap[far]) far = j;
    }
    if (!(gap[far] > 0)) break;
    next = free[far];
  }
  return loads;
}

std::vector<Eigen::VectorXd> to_level(const std::vector<Eigen::VectorXd>& fine_forces,
                                      const TetMesh& finest, const TetMesh& level) {
  if (&level == &finest || fine_forces.empty()) return fine_forces;
  const TetLocator locator(level);
  std::vector<Eigen::VectorXd> out(
      fine_forces.size(), Eigen::VectorXd::Zero(3 * static_cast<Eigen::Index>(level.points.size())));
  for (std::size_t i = 0; i < finest.points.size(); ++i) {
    const auto at_point = [&](const Eigen::VectorXd& f) { return f.segment<3>(3 * static_cast<Eigen::Index>(i)); };
    if (std::none_of(fine_forces.begin(), fine_forces.end(),
                     [&](const Eigen::VectorXd& f) { return !at_point(f).isZero(0); }))
      continue;
    const TetLocation at = locator.locate(finest.points[i]);
    for (std::size_t k = 0; k < fine_forces.size(); ++k)
      for (int a = 0; a < 4; ++a)
        out[k].segment<3>(3 * level.tets[at.tet][a]) += at.bary[a] * at_point(fine_forces[k]);
  }
  return out;
}

std::vector<Eigen::VectorXd> point_forces(const std::vector<LocalLoad>& loads,
                                          const TetMesh& finest) {
  std::vector<Eigen::VectorXd> out;
  for (const LocalLoad& load : loads) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * static_cast<Eigen::Index>(finest.points.size()));
    for (int i : load.points) f.segment<3>(3 * i) = load.force;
    out.push_back(std::move(f));
  }
  return out;
}

std::vector<Eigen::VectorXd> level_loads(const std::vector<LocalLoad>& loads,
                                         const TetMesh& finest, const TetMesh& level) {
  return to_level(point_forces(loads, finest), finest, level);
}

}  // namespace mrsim
