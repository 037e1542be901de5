#include "contact/skin_binding.hpp"

#include <cmath>

#include "hierarchy/tet_locator.hpp"

namespace mrsim {

namespace {

// Round-off dust (a skin vertex that is a vertex of the tet, or lies on one of its faces) is
// removed so that such a vertex follows exactly the points it coincides with.
Bary snapped(Bary b) {
  double sum = 0;
  for (double& x : b) {
    if (std::abs(x) < 1e-12) x = 0;
    sum += x;
  }
  for (double& x : b) x /= sum;
  return b;
}

// The skin's vertices are the finest level's points, bit for bit (a boundary skin of it).
bool is_boundary_of(const Skin& skin, const TetMesh& mesh) {
  if (skin.point.size() != skin.rest.size()) return false;
  for (std::size_t s = 0; s < skin.rest.size(); ++s) {
    const int p = skin.point[s];
    if (p < 0 || p >= static_cast<int>(mesh.points.size()) || mesh.points[p] != skin.rest[s])
      return false;
  }
  return true;
}

}  // namespace

SkinBinding bind_skin(const Skin& skin, const std::vector<const TetMesh*>& levels) {
  std::vector<TetLocator> locators;
  locators.reserve(levels.size());
  for (const TetMesh* mesh : levels) locators.emplace_back(*mesh);
  return bind_skin(skin, locators);
}

SkinBinding bind_skin(const Skin& skin, const std::vector<TetLocator>& levels,
                      const Embedding* finest_in_coarser) {
  SkinBinding b;
  const std::size_t n = skin.rest.size();
  const std::size_t L = levels.size();
  // The level below the finest has located every finest point already (the level links, by
  // the same locator): the same query, so the same answer.
  const bool reuse = finest_in_coarser && L >= 2 && finest_in_coarser->tet.size() ==
                     levels.back().mesh().points.size() && is_boundary_of(skin, levels.back().mesh());
  for (std::size_t l = 0; l < L; ++l) {
    std::vector<int> tet(n);
    std::vector<Bary> bary(n);
    for (std::size_t s = 0; s < n; ++s) {
      if (reuse && l + 2 == L) {
        tet[s] = finest_in_coarser->tet[skin.point[s]];
        bary[s] = snapped(finest_in_coarser->bary[skin.point[s]]);
        continue;
      }
      const TetLocation at = levels[l].locate(skin.rest[s]);
      tet[s] = at.tet;
      bary[s] = snapped(at.bary);
    }
    b.tet.push_back(std::move(tet));
    b.bary.push_back(std::move(bary));
  }
  return b;
}

}  // namespace mrsim
