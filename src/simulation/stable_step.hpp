#pragma once
// The step a scenario may use (method.md §5.2, Courant part; validation.md §2.7): every level
// that may become active must satisfy dt <= C × shortest edge / c_p, doubled for the
// semi-implicit step. A scenario without `time.substeps` gets the smallest power of two of
// steps per frame that does (a power of two, so that the time levels of issue 5 nest in it).
#include <string>
#include <vector>

#include "mesh/tet_mesh.hpp"
#include "scenario/scenario.hpp"

namespace mrsim {

/// Shortest edge of a mesh (m).
double shortest_edge(const TetMesh& mesh);

struct StableStep {
  double dt = 0;   // s, the estimate: min over the levels that may become active
  int level = 0;   // the level that sets it
};

/// The stable step estimate of the scenario's levels 0..max_level (0 only when space
/// adaptivity is off).
StableStep stable_step(const Scenario& sc, const std::vector<const TetMesh*>& meshes);

/// The scenario with time.substeps filled in when it was omitted (also in `resolved`, so the
/// written scenario.yaml reruns identically), with an info line saying so; when it was given
/// and the step exceeds the estimate, a warning naming the level and the substeps needed.
Scenario with_stable_substeps(const Scenario& sc, const std::vector<const TetMesh*>& meshes);

}  // namespace mrsim
