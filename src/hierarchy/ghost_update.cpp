#include "hierarchy/ghost_update.hpp"

#include "hierarchy/barycentric_rows.hpp"

namespace mrsim {

namespace {

// Each ghost's sources straight from the links (Embedding::source), not through its tet.
void from_tets(RowBuild build, const std::vector<int>& points, const Embedding& emb,
               const LevelFields& source, LevelFields& target) {
  interpolate_rows(build, points, emb.source.data(), emb.bary.data(), source.u, source.v,
                   target.u, target.v);
}

}  // namespace

void update_ghosts(const Hierarchy& h, const StatusLists& lists, std::vector<LevelFields>& fields) {
  const int L = h.num_levels();
  const RowBuild build = row_build();
  for (int l = L - 2; l >= 0; --l)
    from_tets(build, lists.ghost_sub(l), h.links(l).child_tet, fields[l + 1], fields[l]);
  for (int l = 1; l < L; ++l)
    from_tets(build, lists.ghost_iface(l), h.links(l).parent_tet, fields[l - 1], fields[l]);
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
