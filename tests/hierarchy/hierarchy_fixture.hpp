#pragma once
// Three independent meshes of one box (not nested: different resolutions, jittered interiors),
// the situation of method.md §4.1.
#include <cstdint>
#include <memory>
#include <random>

#include "hierarchy/hierarchy.hpp"
#include "mesh/box_mesh.hpp"

namespace mrsim::testing {

/// Independent box meshes of 0.1 x 0.06 x 0.04 m at the given cell counts, interior points
/// jittered by ±`jitter` of a cell so that no level is nested in another.
inline std::vector<TetMesh> jittered_box_levels(const std::vector<std::array<int, 3>>& cells,
                                                unsigned seed, double jitter) {
  std::vector<TetMesh> meshes;
  std::mt19937 rng(seed);
  for (const auto& c : cells) {
    TetMesh m = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.06, 0.04), c[0], c[1], c[2]);
    std::uniform_real_distribution<double> d(-jitter, jitter);
    const Vec3 h(0.1 / c[0], 0.06 / c[1], 0.04 / c[2]);
    for (Vec3& p : m.points)
      if (p.x() > 1e-9 && p.x() < 0.1 - 1e-9 && p.y() > 1e-9 && p.y() < 0.06 - 1e-9 &&
          p.z() > 1e-9 && p.z() < 0.04 - 1e-9)
        p += Vec3(d(rng) * h.x(), d(rng) * h.y(), d(rng) * h.z());
    meshes.push_back(std::move(m));
  }
  return meshes;
}

/// Dirichlet masks per level (HierarchySetup::fixed): 1 where `fixed(X)` holds at rest.
template <class Pred>
std::vector<std::vector<std::uint8_t>> fixed_where(const std::vector<TetMesh>& meshes, Pred fixed) {
  std::vector<std::vector<std::uint8_t>> masks(meshes.size());
  for (size_t l = 0; l < meshes.size(); ++l)
    for (const Vec3& X : meshes[l].points) masks[l].push_back(fixed(X) ? 1 : 0);
  return masks;
}

struct ThreeLevels {
  std::vector<TetMesh> meshes;
  std::vector<PointAdjacency> adj;
  std::vector<HierarchyLevel> levels;

  explicit ThreeLevels(std::vector<std::array<int, 3>> cells = {{3, 2, 2}, {7, 4, 3}, {13, 8, 6}})
      : meshes(jittered_box_levels(cells, 17, 0.2)) {
    for (const auto& m : meshes)
      adj.push_back(build_point_adjacency(static_cast<int>(m.points.size()), m.tets));
    for (size_t l = 0; l < meshes.size(); ++l) levels.push_back({&meshes[l], &adj[l]});
  }
  Hierarchy make() const { return Hierarchy(levels, build_level_links(levels)); }
};

}  // namespace mrsim::testing
