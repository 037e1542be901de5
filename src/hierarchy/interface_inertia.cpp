#include "hierarchy/interface_inertia.hpp"

#include <cmath>
#include <span>

#include "hierarchy/merged_rows.hpp"

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

// What a level's ghosts received from its own tets (before any chain): where the mass they
// cannot pass on goes back to.
std::vector<double> own_masses(const InertiaLevel& lv, const StatusLists& lists, int l,
                               const std::vector<PointInertia>& out) {
  std::vector<double> own;
  if (!lv.weight) return own;
  own.assign(out.size(), 0.0);
  for (const auto* ghosts : {&lists.ghost_iface(l), &lists.ghost_sub(l)})
    for (int g : *ghosts) own[g] = out[g].mass;
  return own;
}

// A ghost's mass to the vertices of its source tet (one ghost of `ghosts`): the diagonal of its
// consistent mass, b_k² to source k, hop by hop along a chain of ghosts. What that leaves,
// (1 − Σ b_k²) of it, stays on the ghost's own level: each of its tets gives the active
// vertices it has (one at least: a live tet has a share) the part it gave the ghost, so the
// total inertial mass is the simulated volume's. Without it a mixed beam lost 2–3 % of its mass
// near the interface and vibrated 3.4 % faster than either level alone. A ghost with nothing of
// its own (a link of a chain) passes its mass on in the proportions b_k² / Σ b_j², whole.
void pass_mass_on(const std::vector<int>& ghosts, const Embedding& emb, const TetMesh& source_mesh,
                  const Hierarchy& h, int l, const InertiaLevel& lv,
                  const std::vector<double>& own, std::vector<double>& stay,
                  std::vector<PointInertia>& from, std::vector<PointInertia>& to) {
  bool left = false;
  for (int g : ghosts) {
    if (!(*lv.free_point)[g]) continue;  // held by the support, like its force
    const Bary& b = emb.bary[g];
    const Tet& t = source_mesh.tets[emb.tet[g]];
    const PointInertia& p = from[g];
    double squares = 0;
    for (int k = 0; k < 4; ++k) squares += b[k] * b[k];
    const bool keeps = !own.empty() && own[g] > 0;
    const double scale = keeps ? 1.0 : 1.0 / squares;  // Σ b_k² ≥ 1/4 when Σ b_k = 1
    for (int k = 0; k < 4; ++k) {
      PointInertia& q = to[t[k]];
      q.mass += scale * b[k] * b[k] * p.mass;
      q.gravity_mass += b[k] * p.gravity_mass;
    }
    if (keeps && squares < 1) {  // signed weights (a ghost outside its source mesh) pass more
      stay[g] = (1 - squares) * p.mass / own[g];  // per unit of what its tets gave it
      left = true;
    }
  }
  if (!left) return;
  const LevelModel& m = *lv.model;
  const double rho = m.law.density;
  for (int t : *lv.tets) {
    const double w = (*lv.weight)[t];
    if (w == 0) continue;
    const Tet& tet = m.geo.tets[t];
    double stays = 0;
    int active = 0;
    for (int a = 0; a < 4; ++a) {
      if (h.state(l, tet[a]) == NodeState::Active) ++active;
      else stays += stay[tet[a]];
    }
    if (stays == 0 || active == 0) continue;
    const double each = stays * w * rho * m.geo.volume[t] / 4.0 / active;
    for (int a = 0; a < 4; ++a)
      if (h.state(l, tet[a]) == NodeState::Active) from[tet[a]].mass += each;
  }
  for (int g : ghosts) stay[g] = 0;
}

struct OwnBound {
  double stiffness = 0, damping = 0;
};

// A ghost's own stiffness and damping bounds to the active points that move it, along its
// whole row c (the chain composed; its mass went hop by hop, above, and is final here). For any
// a_k > 0, |Σ c_k u_k|² ≤ (Σ_j c_j²/a_j) Σ_k a_k |u_k|² (Cauchy–Schwarz), so point k takes
// a_k Σ_j c_j²/a_j of the ghost's bound. a_k = |c_k| (the rule hop by hop) piles a coarse
// ghost's stiffness on the light fine points at the fringe of a refined region; a_k = m_k
// spreads the rank-one term's own eigenvalue over every point of a wide row. a_k = m_k √|c_k|
// is tighter than both, measured (docs/integrators.md "The stable step").
void pass_bounds_on(const Hierarchy& h, const std::vector<int>& ghosts, int l,
                    const std::vector<const std::vector<std::uint8_t>*>& free,
                    const OwnBound* own, MergedRows& rows,
                    std::vector<std::vector<PointInertia>>& out) {
  for (size_t i = 0; i < ghosts.size(); ++i) {
    const int g = ghosts[i];
    if (!(*free[l])[g]) continue;
    const MergedRows::Span row = rows.row(h, free, l, g);
    const std::span<const ActiveTerm> terms(rows.terms().data() + row.begin,
                                            rows.terms().data() + row.end);
    double q = 0;  // Σ_j c_j² / a_j; |c|^1.5 as |c|·√|c|: pow() was a quarter of this pass
    for (const ActiveTerm& t : terms)
      if (t.level >= 0 && out[t.level][t.point].mass > 0) {
        const double c = std::abs(t.weight);
        q += c * std::sqrt(c) / out[t.level][t.point].mass;
      }
    for (const ActiveTerm& t : terms) {
      if (t.level < 0) continue;  // the support does not move
      PointInertia& p = out[t.level][t.point];
      const double share = std::sqrt(std::abs(t.weight)) * p.mass * q;
      p.stiffness += share * own[i].stiffness;
      p.damping += share * own[i].damping;
    }
  }
}

}  // namespace

void interface_inertia(const Hierarchy& h, const StatusLists& lists,
                       const std::vector<InertiaLevel>& levels, bool transfer,
                       std::vector<std::vector<PointInertia>>& out, MergedRows& rows) {
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
  // The ghosts' own bounds, in the order of their lists, before their masses chain.
  std::vector<OwnBound> own;
  std::vector<const std::vector<std::uint8_t>*> free(L);
  for (int l = 0; l < L; ++l) {
    free[l] = levels[l].free_point;
    for (const auto* ghosts : {&lists.ghost_iface(l), &lists.ghost_sub(l)})
      for (int g : *ghosts) own.push_back({out[l][g].stiffness, out[l][g].damping});
  }
  // The order of transfer_ghost_forces: a chain of ghosts hands its mass on until it reaches
  // active points.
  std::vector<std::vector<double>> own_mass(L), stay(L);
  for (int l = 0; l < L; ++l) {
    own_mass[l] = own_masses(levels[l], lists, l, out[l]);
    stay[l].assign(own_mass[l].size(), 0.0);
  }
  for (int l = L - 1; l >= 1; --l)
    pass_mass_on(lists.ghost_iface(l), h.links(l).parent_tet, *h.level(l - 1).mesh, h, l,
                 levels[l], own_mass[l], stay[l], out[l], out[l - 1]);
  for (int l = 0; l + 1 < L; ++l)
    pass_mass_on(lists.ghost_sub(l), h.links(l).child_tet, *h.level(l + 1).mesh, h, l,
                 levels[l], own_mass[l], stay[l], out[l], out[l + 1]);
  rows.clear();  // the statuses changed since its last use
  const OwnBound* next = own.data();
  for (int l = 0; l < L; ++l)
    for (const auto* ghosts : {&lists.ghost_iface(l), &lists.ghost_sub(l)}) {
      pass_bounds_on(h, *ghosts, l, free, next, rows, out);
      next += ghosts->size();
    }
}

}  // namespace mrsim
