#include "physics/lumped_mass.hpp"

namespace mrsim {

std::vector<double> lumped_masses(const TetGeometry& geo, const PointAdjacency& adj,
                                  double density) {
  const int n = adj.num_points();
  std::vector<double> m(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double v = 0;
    for (int s = adj.inc_start[i]; s < adj.inc_start[i + 1]; ++s) v += geo.volume[adj.inc_tet[s]];
    m[i] = density * v / 4.0;
  }
  return m;
}

}  // namespace mrsim
