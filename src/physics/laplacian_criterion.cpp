#include "physics/laplacian_criterion.hpp"
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

void laplacian_criterion(const LevelModel& m, const Vec3* u, std::vector<double>& criterion) {
  const int n = m.num_points();
  criterion.resize(n);
  parallel_for(n, [&](int i) {
    criterion[i] = m.mean_edge[i] * corrected_laplacian(m, i, u).norm();
  });
}

}  // namespace mrsim
