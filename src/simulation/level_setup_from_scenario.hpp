#pragma once
// Translation of the validated scenario into the physics setup of the levels.
#include "scenario/scenario.hpp"
#include "simulation/hierarchical_simulation.hpp"
#include "simulation/space_adaptivity.hpp"

namespace mrsim {

MaterialLaw material_law(const MaterialSpec& spec);

/// Step dt = frame_dt / substeps; fixed points selected on every level (may throw InputError).
HierarchySetup hierarchy_setup(const Scenario& scenario, const std::vector<const TetMesh*>& meshes);

SpaceAdaptivitySettings space_settings(const Scenario& scenario);

}  // namespace mrsim
