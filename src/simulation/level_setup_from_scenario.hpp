#pragma once
// Translation of the validated scenario into the physics setup of one level.
#include "scenario/scenario.hpp"
#include "simulation/level_simulation.hpp"

namespace mrsim {

MaterialLaw material_law(const MaterialSpec& spec);

/// Step dt = frame_dt / substeps; fixed points selected on `mesh` (may throw InputError).
LevelSetup level_setup(const Scenario& scenario, const TetMesh& mesh);

/// Largest step the explicit schemes are safe with on this level: 0.5 × shortest edge / c_p
/// (validation.md §2.7, measured factor 0.62–0.76), doubled for the semi-implicit step.
double recommended_max_dt(const LevelModel& model, Integrator integrator);

}  // namespace mrsim
