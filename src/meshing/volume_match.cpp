#include "meshing/volume_match.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>

namespace mrsim {
namespace {

/// Outward area-weighted normal (not normalised) summed at each point; zero inside.
std::vector<Vec3> boundary_normals(const TetMesh& mesh) {
  // A face of a tet, stored sorted, with the tet's corners ordered so that (a, b, c) faces
  // away from the fourth corner.
  std::map<std::array<int, 3>, std::pair<int, std::array<int, 3>>> faces;
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (const Tet& t : mesh.tets) {
    for (const auto& f : kFaces) {
      std::array<int, 3> oriented{t[f[0]], t[f[1]], t[f[2]]};
      std::array<int, 3> key = oriented;
      std::sort(key.begin(), key.end());
      auto [it, inserted] = faces.try_emplace(key, 1, oriented);
      if (!inserted) ++it->second.first;
    }
  }
  std::vector<Vec3> normals(mesh.points.size(), Vec3::Zero());
  for (const auto& [key, use] : faces) {
    if (use.first != 1) continue;
    const auto& [a, b, c] = use.second;
    const Vec3 n = 0.5 * (mesh.points[b] - mesh.points[a]).cross(mesh.points[c] - mesh.points[a]);
    for (int v : use.second) normals[v] += n;
  }
  for (Vec3& n : normals) {
    if (n.squaredNorm() > 0.0) n.normalize();
  }
  return normals;
}

double volume_with_offset(const TetMesh& mesh, const std::vector<Vec3>& normals, double offset,
                          double* min_tet_volume) {
  double total = 0.0, smallest = INFINITY;
  for (const Tet& t : mesh.tets) {
    std::array<Vec3, 4> p;
    for (int c = 0; c < 4; ++c) p[c] = mesh.points[t[c]] + offset * normals[t[c]];
    const double v = signed_volume(p[0], p[1], p[2], p[3]);
    total += v;
    smallest = std::min(smallest, v);
  }
  if (min_tet_volume) *min_tet_volume = smallest;
  return total;
}

}  // namespace

double match_volume(TetMesh& mesh, double target_volume) {
  const std::vector<Vec3> normals = boundary_normals(mesh);
  // V(d) is a cubic in d, nearly linear for small d: a few secant steps solve it.
  double d0 = 0.0, v0 = volume_with_offset(mesh, normals, 0.0, nullptr);
  double d1 = 1e-3 * std::cbrt(target_volume), v1 = volume_with_offset(mesh, normals, d1, nullptr);
  for (int step = 0; step < 30 && std::abs(v1 - target_volume) > 1e-12 * target_volume && v1 != v0; ++step) {
    const double d2 = d1 + (target_volume - v1) * (d1 - d0) / (v1 - v0);
    d0 = d1, v0 = v1;
    d1 = d2, v1 = volume_with_offset(mesh, normals, d1, nullptr);
  }
  double offset = std::isfinite(d1) ? d1 : 0.0;
  // Keep every tet positive: the smallest tet must keep at least a tenth of its volume.
  double smallest_before = 0.0, smallest = 0.0;
  volume_with_offset(mesh, normals, 0.0, &smallest_before);
  for (int halving = 0; halving < 20; ++halving) {
    volume_with_offset(mesh, normals, offset, &smallest);
    if (smallest >= 0.1 * smallest_before) break;
    offset *= 0.5;
  }
  if (smallest < 0.1 * smallest_before) offset = 0.0;
  for (std::size_t i = 0; i < mesh.points.size(); ++i) mesh.points[i] += offset * normals[i];
  return offset;
}

}  // namespace mrsim
