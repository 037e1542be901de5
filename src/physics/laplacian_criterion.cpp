#include "physics/laplacian_criterion.hpp"
#include "core/parallel.hpp"

namespace mrsim {

Vec3 corrected_laplacian(const LevelModel& m, int i, const Vec3* u) {
  Mat3 Gbar = Mat3::Zero();
  double vsum = 0;
  for (int s = m.adj.inc_start[i]; s < m.adj.inc_start[i + 1]; ++s) {
    const int t = m.adj.inc_tet[s];
    Gbar += m.geo.volume[t] * tet_gradient(m.geo.grad[t], m.geo.tets[t], u);
    vsum += m.geo.volume[t];
  }
  Gbar /= vsum;
  Vec3 L = Vec3::Zero();
  for (int s = m.adj.inc_start[i]; s < m.adj.inc_start[i + 1]; ++s) {
    const int t = m.adj.inc_tet[s];
    const Mat3 G = tet_gradient(m.geo.grad[t], m.geo.tets[t], u);
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
