#pragma once
// Frame diagnostics of the multiresolution state, over the simulated (active) points only, so
// they cost O(active) like a step. A region is simulated on one level, so summing levels counts
// each part of the body about once (forced child-tet vertices overlap slightly, method.md §4.6).
#include "simulation/hierarchical_simulation.hpp"

namespace mrsim {

struct Energies {
  double kinetic = 0;           // J, Σ ½ m v² over active points
  double internal_kinetic = 0;  // J, relative to the centre-of-mass velocity of those points
  double elastic = 0;           // J, Σ V_t W(E_t) × (active vertices of t)/4
};

Energies hierarchy_energies(const HierarchicalSimulation& sim);
double max_active_displacement(const HierarchicalSimulation& sim);
/// Force the supports exert (N): minus the sum of the last evaluated forces on the fixed points
/// of every level (active ones, and ghosts whose force goes to the support). At rest it
/// balances the weight and the loads.
Vec3 support_reaction(const HierarchicalSimulation& sim);

}  // namespace mrsim
