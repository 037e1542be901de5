#include "hierarchy/tet_shares.hpp"

namespace mrsim {

void active_tet_shares(const Hierarchy& h, int level, const std::vector<int>& tets,
                       std::vector<double>& share) {
  const TetMesh& mesh = *h.level(level).mesh;
  for (int t : tets) {
    int active = 0;
    for (int v : mesh.tets[t]) active += h.state(level, v) == NodeState::Active;
    share[t] = active / 4.0;
  }
}

}  // namespace mrsim
