#include "hierarchy/ghost_force_transfer.hpp"

#include "hierarchy/barycentric_rows.hpp"

namespace mrsim {

namespace {

// Each ghost's sources straight from the links (Embedding::source), not through its tet.
void to_tets(RowBuild build, const std::vector<int>& ghosts, const Embedding& emb,
             const Vec3* ghost_force, Vec3* source_force) {
  scatter_rows(build, ghosts, emb.source.data(), emb.bary.data(), ghost_force, source_force);
}

// iface(l), sub(l): the level's interface and subdivided ghosts to transfer.
template <class Iface, class Sub>
void transfer(const Hierarchy& h, Iface iface, Sub sub, std::vector<Vec3*>& f) {
  const int L = h.num_levels();
  const RowBuild build = row_build();
  for (int l = L - 1; l >= 1; --l)
    to_tets(build, iface(l), h.links(l).parent_tet, f[l], f[l - 1]);
  for (int l = 0; l + 1 < L; ++l)
    to_tets(build, sub(l), h.links(l).child_tet, f[l], f[l + 1]);
}

}  // namespace

void transfer_ghost_forces(const Hierarchy& h, const GhostSelection& ghosts, std::vector<Vec3*>& f) {
  transfer(h, [&](int l) -> const std::vector<int>& { return *ghosts.iface[l]; },
           [&](int l) -> const std::vector<int>& { return *ghosts.sub[l]; }, f);
}

void transfer_ghost_forces(const Hierarchy& h, const StatusLists& lists, std::vector<Vec3*>& f) {
  transfer(h, [&](int l) -> const std::vector<int>& { return lists.ghost_iface(l); },
           [&](int l) -> const std::vector<int>& { return lists.ghost_sub(l); }, f);
}

}  // namespace mrsim
