#pragma once
// The levels of a scenario are one object meshed several times, coarse to fine (method.md §3):
// checked before anything runs (issue 18 defect 10). `check` accepted a beam level and a liver
// level (`run` then diverged), levels listed fine to coarse and the same mesh twice.
#include <vector>

#include "mesh/tet_mesh.hpp"
#include "scenario/scenario.hpp"

namespace mrsim {

/// Throws InputError naming the level when two levels are the same file, when a level does
/// not have more tets than the one before it, or when a level's volume differs from the finest
/// level's by more than 25 % or its bounding-box centre lies further than a quarter of the
/// finest level's box diagonal from the finest level's.
void check_level_consistency(const Scenario& sc, const std::vector<const TetMesh*>& meshes);

}  // namespace mrsim
