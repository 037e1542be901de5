#include "physics/point_adjacency.hpp"

#include <algorithm>

namespace mrsim {

namespace {

void build_incidence(PointAdjacency& a, int n, const std::vector<Tet>& tets) {
  a.inc_start.assign(n + 1, 0);
  for (const Tet& t : tets)
    for (int v : t) ++a.inc_start[v + 1];
  for (int i = 0; i < n; ++i) a.inc_start[i + 1] += a.inc_start[i];
  a.inc_tet.resize(a.inc_start[n]);
  a.inc_local.resize(a.inc_start[n]);
  std::vector<int> fill(a.inc_start.begin(), a.inc_start.end() - 1);
  for (int t = 0; t < static_cast<int>(tets.size()); ++t)
    for (int k = 0; k < 4; ++k) {
      const int slot = fill[tets[t][k]]++;
      a.inc_tet[slot] = t;  // ascending tet order: a fixed gather order
      a.inc_local[slot] = static_cast<std::int8_t>(k);
    }
}

// Each point's neighbours, deduplicated with a mark per point (a vertex is reached through each
// of the tets it shares with i: about four times) before the few that remain are sorted.
void build_neighbours(PointAdjacency& a, int n, const std::vector<Tet>& tets) {
  a.nbr_start.assign(n + 1, 0);
  a.nbr.clear();
  a.nbr.reserve(a.inc_start[n] * 3 / 4);
  std::vector<int> mark(n, -1);
  for (int i = 0; i < n; ++i) {
    const auto first = static_cast<std::ptrdiff_t>(a.nbr.size());
    for (int s = a.inc_start[i]; s < a.inc_start[i + 1]; ++s)
      for (int v : tets[a.inc_tet[s]])
        if (v != i && mark[v] != i) {
          mark[v] = i;
          a.nbr.push_back(v);
        }
    std::sort(a.nbr.begin() + first, a.nbr.end());
    a.nbr_start[i + 1] = static_cast<int>(a.nbr.size());
  }
}

}  // namespace

PointAdjacency build_point_adjacency(int num_points, const std::vector<Tet>& tets) {
  PointAdjacency a;
  build_incidence(a, num_points, tets);
  build_neighbours(a, num_points, tets);
  return a;
}

int find_neighbour_entry(const PointAdjacency& adj, int i, int j) {
  const auto first = adj.nbr.begin() + adj.nbr_start[i];
  const auto last = adj.nbr.begin() + adj.nbr_start[i + 1];
  const auto it = std::lower_bound(first, last, j);
  return (it != last && *it == j) ? static_cast<int>(it - adj.nbr.begin()) : -1;
}

}  // namespace mrsim
