#include "hierarchy/active_row.hpp"

namespace mrsim {

void append_active_row(const Hierarchy& h,
                       const std::vector<const std::vector<std::uint8_t>*>& free_point, int l,
                       int p, double weight, std::vector<ActiveTerm>& out) {
  const NodeState s = h.state(l, p);
  if (s == NodeState::Active) {
    out.push_back({l, p, weight});
    return;
  }
  if (!(*free_point[l])[p]) {  // a Dirichlet ghost or inactive point stays at rest
    out.push_back({-1, p, weight});
    return;
  }
  const bool finer = s == NodeState::GhostSub;
  const Embedding& e = finer ? h.links(l).child_tet : h.links(l).parent_tet;
  const int source = finer ? l + 1 : l - 1;
  const Tet& t = h.level(source).mesh->tets[e.tet[p]];
  for (int k = 0; k < 4; ++k)
    if (e.bary[p][k] != 0)
      append_active_row(h, free_point, source, t[k], weight * e.bary[p][k], out);
}

}  // namespace mrsim
