#include "hierarchy/level_links.hpp"

#include <cmath>

#include <algorithm>
#include <limits>

#include "hierarchy/tet_locator.hpp"

namespace mrsim {

namespace {

Embedding embed(const TetMesh& points_of, const TetMesh& mesh, const TetLocator& into) {
  Embedding e;
  const size_t n = points_of.points.size();
  e.tet.resize(n);
  e.bary.resize(n);
  e.source.resize(n);
#pragma omp parallel for schedule(dynamic, 256)
  for (size_t i = 0; i < n; ++i) {
    const TetLocation l = into.locate(points_of.points[i]);
    e.tet[i] = l.tet;
    e.bary[i] = l.bary;
    const Tet& t = mesh.tets[l.tet];
    e.source[i] = {t[0], t[1], t[2], t[3]};
  }
  return e;
}

Embedding none(size_t n) {
  Embedding e;
  e.tet.assign(n, -1);
  e.bary.assign(n, Bary{});
  e.source.assign(n, {-1, -1, -1, -1});
  return e;
}

// parent(q) = the nearest coarse point among the vertices of q's parent tet and their
// neighbours (the Voronoi cell of §4.3 step 2); ties go to the lowest index.
int voronoi_parent(const Vec3& x, int parent_tet, const HierarchyLevel& coarse) {
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  auto consider = [&](int p) {
    const double d = (coarse.mesh->points[p] - x).squaredNorm();
    if (d < best_d || (d == best_d && p < best)) {
      best = p;
      best_d = d;
    }
  };
  for (int v : coarse.mesh->tets[parent_tet]) {
    consider(v);
    for (int e = coarse.adj->nbr_start[v]; e < coarse.adj->nbr_start[v + 1]; ++e)
      consider(coarse.adj->nbr[e]);
  }
  return best;
}

void build_sets(LevelLinks& coarse, const LevelLinks& fine_links, const HierarchyLevel& coarse_level,
                const HierarchyLevel& fine) {
  const int nc = static_cast<int>(coarse_level.mesh->points.size());
  std::vector<std::vector<int>> kids(nc);
  for (int q = 0; q < static_cast<int>(fine_links.parent.size()); ++q)
    kids[fine_links.parent[q]].push_back(q);
  std::vector<int> active, ghosts;
  for (int p = 0; p < nc; ++p) {
    coarse.children.push_row(kids[p]);
    active = kids[p];
    if (!kids[p].empty())  // childless points never split (§4.3 step 5)
      for (int v : fine.mesh->tets[coarse.child_tet.tet[p]]) active.push_back(v);
    std::sort(active.begin(), active.end());
    active.erase(std::unique(active.begin(), active.end()), active.end());
    ghosts.clear();
    for (int a : active)
      for (int e = fine.adj->nbr_start[a]; e < fine.adj->nbr_start[a + 1]; ++e)
        if (!std::binary_search(active.begin(), active.end(), fine.adj->nbr[e]))
          ghosts.push_back(fine.adj->nbr[e]);
    std::sort(ghosts.begin(), ghosts.end());
    ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
    coarse.active_set.push_row(active);
    coarse.ghost_set.push_row(ghosts);
  }
}

// Reverse of parent_tet: which finer points interpolate from this point (for merges, which
// must keep a point as support while a finer interface ghost still reads it).
void build_dependents(LevelLinks& coarse, const LevelLinks& fine_links,
                      const HierarchyLevel& coarse_level) {
  std::vector<std::vector<int>> deps(coarse_level.mesh->points.size());
  for (int g = 0; g < static_cast<int>(fine_links.parent_tet.tet.size()); ++g)
    for (int v : coarse_level.mesh->tets[fine_links.parent_tet.tet[g]]) deps[v].push_back(g);
  for (auto& row : deps) coarse.dependents.push_row(row);
}

}  // namespace

std::vector<LevelLinks> build_level_links(const std::vector<HierarchyLevel>& levels) {
  std::vector<TetLocator> locators;
  locators.reserve(levels.size());
  for (const auto& lv : levels) locators.emplace_back(*lv.mesh);
  return build_level_links(levels, locators);
}

std::vector<LevelLinks> build_level_links(const std::vector<HierarchyLevel>& levels,
                                          const std::vector<TetLocator>& locators) {
  const size_t L = levels.size();
  std::vector<LevelLinks> links(L);
  for (size_t l = 0; l < L; ++l) {
    const size_t n = levels[l].mesh->points.size();
    links[l].parent_tet =
        l > 0 ? embed(*levels[l].mesh, *levels[l - 1].mesh, locators[l - 1]) : none(n);
    links[l].child_tet =
        l + 1 < L ? embed(*levels[l].mesh, *levels[l + 1].mesh, locators[l + 1]) : none(n);
    links[l].parent.assign(n, -1);
    if (l > 0)
      for (size_t q = 0; q < n; ++q)
        links[l].parent[q] = voronoi_parent(levels[l].mesh->points[q], links[l].parent_tet.tet[q],
                                            levels[l - 1]);
  }
  for (size_t l = 0; l + 1 < L; ++l) {
    build_sets(links[l], links[l + 1], levels[l], levels[l + 1]);
    build_dependents(links[l], links[l + 1], levels[l]);
  }
  for (size_t p = 0; p < levels[L - 1].mesh->points.size(); ++p) {  // finest: empty rows
    links[L - 1].children.push_row({});
    links[L - 1].active_set.push_row({});
    links[L - 1].ghost_set.push_row({});
    links[L - 1].dependents.push_row({});
  }
  return links;
}

}  // namespace mrsim
