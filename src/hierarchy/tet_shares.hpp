#pragma once
// Which share of each tet a level simulates (energy-consistent coupling, docs/hierarchy.md):
// every active point owns a quarter of each incident tet, as it owns a quarter of its mass
// (lumped masses, method.md §2.4). A tet with k active vertices counts for k/4 of its strain
// energy; summed over the levels, the body's energy and mass are each counted about once.
#include <vector>

#include "hierarchy/hierarchy.hpp"

namespace mrsim {

/// (active vertices of the tet)/4.
double active_share(const Hierarchy& h, int level, const Tet& tet);

/// share[t] = active_share of t for every tet in `tets`; other entries untouched.
void active_tet_shares(const Hierarchy& h, int level, const std::vector<int>& tets,
                       std::vector<double>& share);

}  // namespace mrsim
