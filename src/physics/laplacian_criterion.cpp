#include "physics/laplacian_criterion.hpp"

#include <stdexcept>
#include <string>

#include "core/parallel.hpp"

namespace mrsim {

namespace {

// The two passes of method.md §3.1 at point i: the volume-weighted mean gradient Ḡ over the
// incident tets, then L = -Σ V_t (G_t - Ḡ) ∇N_i^t. `mean_pass(s, t)` and `deviation_pass(s, t)`
// give incidence s's tet gradient in each pass, so the callers differ only in where it comes
// from (computed, kept, cached): the same arithmetic, the same bits.
template <class MeanPass, class DeviationPass>
Vec3 two_passes(const LevelModel& m, int i, MeanPass mean_pass, DeviationPass deviation_pass) {
  Mat3 Gbar = Mat3::Zero();
  double vsum = 0;
  const int first = m.adj.inc_start[i], last = m.adj.inc_start[i + 1];
  for (int s = first; s < last; ++s) {
    const int t = m.adj.inc_tet[s];
    Gbar += m.geo.volume[t] * mean_pass(s, t);
    vsum += m.geo.volume[t];
  }
  Gbar /= vsum;
  Vec3 L = Vec3::Zero();
  for (int s = first; s < last; ++s) {
    const int t = m.adj.inc_tet[s];
    L -= m.geo.volume[t] * ((deviation_pass(s, t) - Gbar) * m.geo.grad[t][m.adj.inc_local[s]]);
  }
  return L / m.lumped_volume[i];
}

}  // namespace

Vec3 corrected_laplacian(const LevelModel& m, int i, const Vec3* u) {
  // Each incident tet's gradient serves twice (the mean, then the deviations from it): kept for
  // the first kKept tets rather than computed again (half this function's work), recomputed
  // beyond them. The same values either way.
  constexpr int kKept = 48;
  Mat3 kept[kKept];
  const int first = m.adj.inc_start[i], last = m.adj.inc_start[i + 1];
  const auto gradient = [&](int t) { return tet_gradient(m.geo.grad[t], m.geo.tets[t], u); };
  return two_passes(
      m, i,
      [&](int s, int t) {
        if (s + kTetPrefetchAhead < last)
          prefetch_tet(m.geo, m.adj.inc_tet[s + kTetPrefetchAhead]);
        const Mat3 G = gradient(t);
        if (s - first < kKept) kept[s - first] = G;
        return G;
      },
      [&](int s, int t) { return s - first < kKept ? kept[s - first] : gradient(t); });
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
  for (const int i : points) {
    const auto cached = [&](int, int t) -> const Mat3& {
      if (cache.slot[t] < 0) {
        for (const int k : tets) cache.slot[k] = -1;
        throw std::logic_error("corrected_criterion: a tet of point " + std::to_string(i) +
                               " is not among the tets given");
      }
      return cache.G[cache.slot[t]];
    };
    criterion[i] = m.mean_edge[i] * two_passes(m, i, cached, cached).norm();
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
