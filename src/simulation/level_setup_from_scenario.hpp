#pragma once
// Translation of the validated scenario into the physics setup of the levels.
#include <cstdint>
#include <vector>

#include "scenario/scenario.hpp"
#include "simulation/hierarchical_simulation.hpp"
#include "simulation/space_adaptivity.hpp"

namespace mrsim {

MaterialLaw material_law(const MaterialSpec& spec);

/// Each level's material: the scenario's, with each coarser level's calibrated tensor when
/// object.calibration asks for it (hierarchy/level_calibration.hpp; computed here, at set-up),
/// and the points it holds: selected once (select_fixed_points() warns), they serve the
/// calibration, the levels' spectra (level_models()) and the simulation (hierarchy_setup()).
struct LevelLaws {
  std::vector<MaterialLaw> laws;              // one per level
  std::vector<LevelCalibration> calibration;  // one per level, or empty
  std::vector<std::vector<std::uint8_t>> held;  // one per level, 1 = held (scenario `fixed`)
};
LevelLaws level_laws(const Scenario& scenario, const std::vector<const TetMesh*>& meshes);

/// Step dt = frame_dt / substeps; fixed points selected on every level (may throw InputError).
/// `laws`: from level_laws() (computed when not given); `skin`: the tools' skin,
/// scenario_skin() of the finest level (built when not given).
HierarchySetup hierarchy_setup(const Scenario& scenario, const std::vector<const TetMesh*>& meshes,
                               const LevelLaws* laws = nullptr, const Skin* skin = nullptr);

SpaceAdaptivitySettings space_settings(const Scenario& scenario);

}  // namespace mrsim
