#include "physics/laplacian_criterion.hpp"

#include <stdexcept>
#include <string>

#include "core/parallel.hpp"

namespace mrsim {

Vec3 corrected_laplacian(const LevelModel& m, int i, const Vec3* u) {
  // Each incident tet's gradient serves twice (the mean, then the deviations from it): kept for
  // the first kKept tets rather than computed again (half this function's work), recomputed
  // beyond them. The same values either way.
  constexpr int kKept = 48;
  Mat3 kept[kKept];
  Mat3 Gbar = Mat3::Zero();
  double vsum = 0;
  const int first = m.adj.inc_start[i], last = m.adj.inc_start[i + 1];
  for (int s = first; s < last; ++s) {
    if (s + kTetPrefetchAhead < last) prefetch_tet(m.geo, m.adj.inc_tet[s + kTetPrefetchAhead]);
    const int t = m.adj.inc_tet[s];
    const Mat3 G = tet_gradient(m.geo.grad[t], m.geo.tets[t], u);
    if (s - first < kKept) kept[s - first] = G;
    Gbar += m.geo.volume[t] * G;
    vsum += m.geo.volume[t];
  }
  Gbar /= vsum;
  Vec3 L = Vec3::Zero();
  for (int s = first; s < last; ++s) {
    const int t = m.adj.inc_tet[s];
    const Mat3 G =
        s - first < kKept ? kept[s - first] : tet_gradient(m.geo.grad[t], m.geo.tets[t], u);
    L -= m.geo.volume[t] * ((G - Gbar) * m.geo.grad[t][m.adj.inc_local[s]]);
  }
  return L / m.lumped_volume[i];
}

void corrected_criterion(const LevelModel& m, std::span<const int> points,
                         std::span<const int> tets, const Vec3* u, TetGradientCache& cache,
                         double* criterion) {
  cache.slot.resize(m.num_tets(), -1);
  cache.G.resize(tets.size());
  for (std::size_t k = 0; k < tets.size(); ++k) {
    if (k + kTetPrefetchAhead < tets.size()) prefetch_tet(m.geo, tets[k + kTetPrefetchAhead]);
    const int t = tets[k];
    cache.slot[t] = static_cast<int>(k);
    cache.G[k] = tet_gradient(m.geo.grad[t], m.geo.tets[t], u);
  }
  // corrected_laplacian()'s two passes, the gradients read from the cache.
  for (const int i : points) {
    const int first = m.adj.inc_start[i], last = m.adj.inc_start[i + 1];
    Mat3 Gbar = Mat3::Zero();
    double vsum = 0;
    for (int s = first; s < last; ++s) {
      const int t = m.adj.inc_tet[s];
      if (cache.slot[t] < 0) {
        for (const int k : tets) cache.slot[k] = -1;
        throw std::logic_error("corrected_criterion: a tet of point " + std::to_string(i) +
                               " is not among the tets given");
      }
      Gbar += m.geo.volume[t] * cache.G[cache.slot[t]];
      vsum += m.geo.volume[t];
    }
    Gbar /= vsum;
    Vec3 L = Vec3::Zero();
    for (int s = first; s < last; ++s) {
      const int t = m.adj.inc_tet[s];
      const Mat3& G = cache.G[cache.slot[t]];
      L -= m.geo.volume[t] * ((G - Gbar) * m.geo.grad[t][m.adj.inc_local[s]]);
    }
    criterion[i] = m.mean_edge[i] * (L / m.lumped_volume[i]).norm();
  }
  for (const int t : tets) cache.slot[t] = -1;
}

void laplacian_criterion(const LevelModel& m, const Vec3* u, std::vector<double>& criterion) {
  const int n = m.num_points();
  criterion.resize(n);
  parallel_for(n, [&](int i) {
    criterion[i] = m.mean_edge[i] * corrected_laplacian(m, i, u).norm();
  });
}

}  // namespace mrsim
