#pragma once
// What a checkpoint takes from a run's simulation and gives back to it (docs/output.md
// "Checkpoints and --resume"). HierarchicalSimulation::checkpoint()/restore() are defined in
// checkpoint_state.cpp; the space adaptivity's share is here.
#include "io/checkpoint_data.hpp"
#include "simulation/hierarchical_simulation.hpp"
#include "simulation/space_adaptivity.hpp"

namespace mrsim {

/// The simulation's state and the adaptivity's split frames at a frame boundary.
SimulationCheckpoint take_checkpoint(const HierarchicalSimulation& sim,
                                     const SpaceAdaptivity& adapt);

/// Both back, on a simulation and adaptivity freshly built from the same scenario. Throws
/// std::invalid_argument or std::runtime_error when the checkpoint does not fit them.
void restore_checkpoint(const SimulationCheckpoint& checkpoint, HierarchicalSimulation& sim,
                        SpaceAdaptivity& adapt);

}  // namespace mrsim
