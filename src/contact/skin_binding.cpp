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

}  // namespace

SkinBinding bind_skin(const Skin& skin, const std::vector<const TetMesh*>& levels) {
  std::vector<TetLocator> locators;
  locators.reserve(levels.size());
  for (const TetMesh* mesh : levels) locators.emplace_back(*mesh);
  return bind_skin(skin, locators);
}

SkinBinding bind_skin(const Skin& skin, const std::vector<TetLocator>& levels) {
  SkinBinding b;
  const std::size_t n = skin.rest.size();
  for (const TetLocator& locator : levels) {
    std::vector<int> tet(n);
    std::vector<Bary> bary(n);
    for (std::size_t s = 0; s < n; ++s) {
      const TetLocation at = locator.locate(skin.rest[s]);
      tet[s] = at.tet;
      bary[s] = snapped(at.bary);
    }
    b.tet.push_back(std::move(tet));
    b.bary.push_back(std::move(bary));
  }
  return b;
}

}  // namespace mrsim
