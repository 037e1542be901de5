#pragma once
// The step a scenario may use (method.md §5.2; docs/integrators.md "The stable step"): every
// point of every level that may become active must satisfy dt <= C × its stable-step estimate
// (physics/stable_step_bound.hpp: Gershgorin bound of its star's stiffness over its mass,
// damping, and the contact penalty the tools can add, contact/contact_bound.hpp), C =
// time.courant. A scenario without `time.substeps` gets the fewest steps per frame that do
// (computed_substeps(): with time levels a power of two, so that they nest in it); one that
// needs more than kMaxSubsteps is an input error naming the point and the cause. During the run the
// estimate follows the topology (interface masses and stiffness through ghosts,
// HierarchicalSimulation::stable_step_in_force).
#include <string>
#include <vector>

#include "contact/skin.hpp"
#include "mesh/tet_mesh.hpp"
#include "physics/level_model.hpp"
#include "scenario/scenario.hpp"
#include "time/steps_per_frame.hpp"

namespace mrsim {

struct LevelLaws;  // simulation/level_setup_from_scenario.hpp

/// Shortest edge of a mesh (m).
double shortest_edge(const TetMesh& mesh);

struct StableStep {
  double dt = 0;      // s, the estimate: min over the points of the levels that may become active
  int level = 0;      // where it is set
  int point = 0;
  std::string cause;  // what sets it there, in words
};

/// Every level's model with its material (level_laws()) and the scenario's integrator: what the
/// stable step and the simulation are built from (the run builds them once and hands them to
/// both: the spectra at set-up are half its cost, docs/performance.md).
std::vector<LevelModel> level_models(const Scenario& sc, const std::vector<const TetMesh*>& meshes,
                                     const LevelLaws& laws);

/// The stable step estimate (before time.courant) of the scenario's levels 0..max_level (0
/// only when space adaptivity is off); held points do not count. `laws`: each level's material
/// and held points (level_laws(), computed when not given); `models`: the levels' models (level_models(), built when not given);
/// `skin`: the tools' skin (scenario_skin(), built when not given).
StableStep stable_step(const Scenario& sc, const std::vector<const TetMesh*>& meshes,
                       const LevelLaws* laws = nullptr,
                       const std::vector<LevelModel>* models = nullptr,
                       const Skin* skin = nullptr);

/// Steps per frame for a step of at most `allowed` (C × the estimate): with time levels the
/// smallest power of two that fits, times 4 (two finer levels for the velocity-change rule);
/// with one global step the smallest multiple of `parts` (adaptivity.space.split_checks) that
/// fits. At most kMaxSubsteps.
long long computed_substeps(double frame_dt, double allowed, bool time_levels, int parts);

/// The scenario with time.substeps filled in when it was omitted (also in `resolved`, so the
/// written scenario.yaml reruns identically), with an info line saying so; when it was given
/// and the step exceeds C × the estimate, a warning naming the level and the substeps needed.
/// Throws InputError when the step needed is beyond kMaxSubsteps per frame.
Scenario with_stable_substeps(const Scenario& sc, const std::vector<const TetMesh*>& meshes,
                              const LevelLaws* laws = nullptr,
                              const std::vector<LevelModel>* models = nullptr,
                              const Skin* skin = nullptr);

}  // namespace mrsim
