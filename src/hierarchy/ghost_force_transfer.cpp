#include "hierarchy/ghost_force_transfer.hpp"

namespace mrsim {

namespace {

void to_tets(const std::vector<int>& ghosts, const Embedding& emb, const TetMesh& source_mesh,
             const Vec3* ghost_force, Vec3* source_force) {
  for (int g : ghosts) {
    const Tet& t = source_mesh.tets[emb.tet[g]];
    for (int k = 0; k < 4; ++k) source_force[t[k]] += emb.bary[g][k] * ghost_force[g];
  }
}

// iface(l), sub(l): the level's interface and subdivided ghosts to transfer.
template <class Iface, class Sub>
void transfer(const Hierarchy& h, Iface iface, Sub sub, std::vector<Vec3*>& f) {
  const int L = h.num_levels();
  for (int l = L - 1; l >= 1; --l)
    to_tets(iface(l), h.links(l).parent_tet, *h.level(l - 1).mesh, f[l], f[l - 1]);
  for (int l = 0; l + 1 < L; ++l)
    to_tets(sub(l), h.links(l).child_tet, *h.level(l + 1).mesh, f[l], f[l + 1]);
}

}  // namespace

void transfer_ghost_forces(const Hierarchy& h, const GhostSelection& ghosts, std::vector<Vec3*>& f) {
  transfer(h, [&](int l) -> const std::vector<int>& { return *ghosts.iface[l]; },
           [&](int l) -> const std::vector<int>& { return *ghosts.sub[l]; }, f);
}

// The same sums as to_tets(), read from one record per ghost.
void to_stencils(const std::vector<int>& ghosts, const std::vector<GhostStencil>& stencils,
                 const Vec3* ghost_force, Vec3* source_force) {
  for (std::size_t k = 0; k < ghosts.size(); ++k) {
    const GhostStencil& s = stencils[k];
    const Vec3 g = ghost_force[ghosts[k]];
    for (int a = 0; a < 4; ++a) source_force[s.source[a]] += s.weight[a] * g;
  }
}

void transfer_ghost_forces(const Hierarchy& h, const StatusLists& lists, std::vector<Vec3*>& f) {
  const int L = h.num_levels();
  for (int l = L - 1; l >= 1; --l)
    to_stencils(lists.ghost_iface(l), lists.iface_stencils(l), f[l], f[l - 1]);
  for (int l = 0; l + 1 < L; ++l)
    to_stencils(lists.ghost_sub(l), lists.sub_stencils(l), f[l], f[l + 1]);
}

}  // namespace mrsim
