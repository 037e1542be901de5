#pragma once
// Divergence guard (issue 2 point 5): a run is declared diverged when its state is not finite,
// or when its internal energy (strain energy + kinetic energy relative to the centre of mass)
// exceeds `energy_factor` × ½ V (λ+2μ): the energy the body would have if every point moved at
// the P-wave speed, or were strained by 100 %. Explicit schemes past their stability limit cross
// it within a few frames; physical runs stay orders of magnitude below it.
#include <optional>
#include <string>

#include "simulation/hierarchical_simulation.hpp"

namespace mrsim {

struct DivergenceGuard {
  double energy_bound = 0;  // J

  static DivergenceGuard for_level(const LevelModel& model, double energy_factor);
  /// A message explaining why the state diverged, or nothing. Looks at active points only.
  std::optional<std::string> check(const HierarchicalSimulation& sim, double internal_energy) const;
};

}  // namespace mrsim
