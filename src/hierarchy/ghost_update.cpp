#include "hierarchy/ghost_update.hpp"

namespace mrsim {

Vec3 interpolate(const Vec3* values, const Tet& tet, const Bary& b) {
  return b[0] * values[tet[0]] + b[1] * values[tet[1]] + b[2] * values[tet[2]] +
         b[3] * values[tet[3]];
}

namespace {

// The same sums as interpolate(), read from one record per ghost.
void from_stencils(const std::vector<int>& points, const std::vector<GhostStencil>& stencils,
                   const LevelFields& source, LevelFields& target) {
  for (std::size_t k = 0; k < points.size(); ++k) {
    const GhostStencil& s = stencils[k];
    const Bary& b = s.weight;
    target.u[points[k]] = b[0] * source.u[s.source[0]] + b[1] * source.u[s.source[1]] +
                          b[2] * source.u[s.source[2]] + b[3] * source.u[s.source[3]];
    target.v[points[k]] = b[0] * source.v[s.source[0]] + b[1] * source.v[s.source[1]] +
                          b[2] * source.v[s.source[2]] + b[3] * source.v[s.source[3]];
  }
}

}  // namespace

void update_ghosts(const Hierarchy& h, const StatusLists& lists, std::vector<LevelFields>& fields) {
  const int L = h.num_levels();
  for (int l = L - 2; l >= 0; --l)
    from_stencils(lists.ghost_sub(l), lists.sub_stencils(l), fields[l + 1], fields[l]);
  for (int l = 1; l < L; ++l)
    from_stencils(lists.ghost_iface(l), lists.iface_stencils(l), fields[l - 1], fields[l]);
}

void interpolate_inactive(const Hierarchy& h, std::vector<LevelFields>& fields) {
  for (int l = 1; l < h.num_levels(); ++l) {
    const auto& emb = h.links(l).parent_tet;
    const TetMesh& coarse = *h.level(l - 1).mesh;
    for (int p = 0; p < h.num_points(l); ++p)
      if (h.state(l, p) == NodeState::Inactive) {
        fields[l].u[p] = interpolate(fields[l - 1].u, coarse.tets[emb.tet[p]], emb.bary[p]);
        fields[l].v[p] = interpolate(fields[l - 1].v, coarse.tets[emb.tet[p]], emb.bary[p]);
      }
  }
}

}  // namespace mrsim
