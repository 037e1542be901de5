#include "hierarchy/tet_shares.hpp"

namespace mrsim {

double active_share(const Hierarchy& h, int level, const Tet& tet) {
  int active = 0;
  for (int v : tet) active += h.state(level, v) == NodeState::Active;
  return active / 4.0;
}

void active_tet_shares(const Hierarchy& h, int level, const std::vector<int>& tets,
                       std::vector<double>& share) {
  const TetMesh& mesh = *h.level(level).mesh;
  for (int t : tets) share[t] = active_share(h, level, mesh.tets[t]);
}

}  // namespace mrsim
