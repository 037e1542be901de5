#include "hierarchy/interface_inertia.hpp"

#include <cmath>

namespace mrsim {

namespace {

void weighted_star(const InertiaLevel& lv, const StatusLists& lists, int l,
                   std::vector<PointInertia>& out) {
  for (const auto* list : {&lists.active(l), &lists.ghost_sub(l), &lists.ghost_iface(l)})
    for (int p : *list) out[p] = PointInertia{};
  const LevelModel& m = *lv.model;
  const double rho = m.law.density;
  for (int t : *lv.tets) {
    const double w = (*lv.weight)[t];
    if (w == 0) continue;
    const double mass = w * rho * m.geo.volume[t] / 4.0;
    const double stiffness = w * m.bounds.stiffness[t], damping = w * m.bounds.damping[t];
    for (int a = 0; a < 4; ++a) {
      PointInertia& p = out[m.geo.tets[t][a]];
      p.mass += mass;
      p.gravity_mass += mass;
      p.stiffness += stiffness;
      p.damping += damping;
    }
  }
}

// A ghost's inertia to the vertices of its source tet (one ghost of `ghosts`).
void pass_on(const std::vector<int>& ghosts, const Embedding& emb, const TetMesh& source_mesh,
             const std::vector<std::uint8_t>& free_point, std::vector<PointInertia>& from,
             std::vector<PointInertia>& to) {
  for (int g : ghosts) {
    if (!free_point[g]) continue;  // held by the support, like its force
    const Bary& b = emb.bary[g];
    double total = 0;
    for (double w : b) total += std::abs(w);
    const Tet& t = source_mesh.tets[emb.tet[g]];
    const PointInertia& p = from[g];
    for (int k = 0; k < 4; ++k) {
      PointInertia& q = to[t[k]];
      q.mass += b[k] * b[k] * p.mass;
      q.gravity_mass += b[k] * p.gravity_mass;
      const double row = std::abs(b[k]) * total;
      q.stiffness += row * p.stiffness;
      q.damping += row * p.damping;
    }
  }
}

}  // namespace

void interface_inertia(const Hierarchy& h, const StatusLists& lists,
                       const std::vector<InertiaLevel>& levels, bool transfer,
                       std::vector<std::vector<PointInertia>>& out) {
  const int L = h.num_levels();
  out.resize(L);
  for (int l = 0; l < L; ++l) {
    const InertiaLevel& lv = levels[l];
    out[l].resize(lv.model->num_points());
    if (lv.weight) {
      weighted_star(lv, lists, l, out[l]);
    } else {
      for (int p : lists.active(l)) out[l][p] = lv.model->star[p];
    }
  }
  if (!transfer) return;
  // The order of transfer_ghost_forces: a chain of ghosts hands its inertia on until it
  // reaches active points.
  for (int l = L - 1; l >= 1; --l)
    pass_on(lists.ghost_iface(l), h.links(l).parent_tet, *h.level(l - 1).mesh,
            *levels[l].free_point, out[l], out[l - 1]);
  for (int l = 0; l + 1 < L; ++l)
    pass_on(lists.ghost_sub(l), h.links(l).child_tet, *h.level(l + 1).mesh, *levels[l].free_point,
            out[l], out[l + 1]);
}

}  // namespace mrsim
