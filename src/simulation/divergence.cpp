#include "simulation/divergence.hpp"

#include <cmath>
#include <sstream>

namespace mrsim {

DivergenceGuard DivergenceGuard::for_level(const LevelModel& model, double energy_factor) {
  double volume = 0;
  for (double v : model.geo.volume) volume += v;
  DivergenceGuard g;
  g.energy_bound = energy_factor * 0.5 * volume * (model.law.lambda + 2 * model.law.mu);
  return g;
}

std::optional<std::string> DivergenceGuard::check(const HierarchicalSimulation& sim,
                                                   double internal_energy) const {
  for (int l = 0; l < sim.num_levels(); ++l)
    for (int i : sim.lists().active(l)) {
      const PointState& s = sim.state(l);
      if (s.u[i].allFinite() && s.v[i].allFinite()) continue;
      std::ostringstream os;
      os << "non-finite displacement or velocity at point " << i << " of level " << l;
      return os.str();
    }
  if (!std::isfinite(internal_energy) || internal_energy > energy_bound) {
    std::ostringstream os;
    os.precision(4);
    os << "internal energy " << internal_energy << " J exceeds the bound " << energy_bound
       << " J (time.divergence.energy_factor x 1/2 V (lambda+2mu)); the time step is probably "
          "above the stability limit: raise time.substeps or use time.integrator: semi_implicit";
    return os.str();
  }
  return std::nullopt;
}

}  // namespace mrsim
