#include "simulation/divergence.hpp"

#include <cmath>
#include <sstream>

namespace mrsim {

namespace {

// Where point p of level l sits in the hierarchy, in words: where interface instabilities start.
std::string place_of(const HierarchicalSimulation& sim, int l, int p) {
  const PointAdjacency& adj = sim.model(l).adj;
  bool finer = false, coarser = false;
  for (int e = adj.nbr_start[p]; e < adj.nbr_start[p + 1]; ++e) {
    const NodeState s = sim.hierarchy().state(l, adj.nbr[e]);
    finer = finer || s == NodeState::GhostSub;
    coarser = coarser || s == NodeState::GhostIface;
  }
  if (finer) return "a coarse point next to the fine region";
  if (coarser) return "a fine point at the edge of its region";
  return "inside level " + std::to_string(l) + "'s region";
}

// The step point p of level l takes: the global one, or its particle's.
double step_of(const HierarchicalSimulation& sim, int l, int p) {
  if (const TimeAdaptivity* ta = sim.time_levels())
    if (ta->level_of(l, p) >= 0) return ta->rules().frame_dt / (1 << ta->level_of(l, p));
  return sim.step();
}

// The free active point whose step is furthest above its stable step estimate, if any is: where
// an instability starts. The first non-finite point is only the first in list order, anywhere
// once the blow-up has spread (liver_probe's finest level alone at 64 substeps, a step twice the
// computed one, first showed it at point 0, within its own estimate).
struct Overstep {
  int level = -1, point = -1;
  double step = 0, estimate = 0;
};

Overstep furthest_above_its_estimate(const HierarchicalSimulation& sim) {
  Overstep worst;
  double ratio = 1;
  for (int l = 0; l < sim.num_levels(); ++l)
    for (int p : sim.lists().active(l)) {
      const double estimate = sim.stable_steps(l)[p];
      if (!sim.state(l).free_point[p] || !(estimate > 0)) continue;
      const double step = step_of(sim, l, p);
      if (step > ratio * estimate) worst = {l, p, step, estimate}, ratio = step / estimate;
    }
  return worst;
}

// The stable estimate in force at the point and the step it took, then the smallest estimate
// in force, and what to change: the step where one is above its estimate, else the load.
std::string step_against_estimate(const HierarchicalSimulation& sim, int l, int p) {
  std::ostringstream os;
  os.precision(4);
  os << "its step " << step_of(sim, l, p) << " s against its stable step estimate "
     << sim.stable_steps(l)[p] << " s";
  const auto& in_force = sim.stable_step_in_force();
  if (in_force.level >= 0)
    os << "; the stable step estimate in force " << in_force.dt << " s (point " << in_force.point
       << " of level " << in_force.level << ", " << place_of(sim, in_force.level, in_force.point)
       << ")";
  if (const Overstep o = furthest_above_its_estimate(sim); o.level >= 0)
    os << "; a step is above its estimate (" << o.step << " s against " << o.estimate
       << " s at point " << o.point << " of level " << o.level
       << "): raise time.substeps or omit it to have it computed";
  else
    os << "; every step is within its estimate: a large deformation, inverted tets or a sudden "
          "load"
       << (sim.semi_implicit() ? "" : ", or use time.integrator: semi_implicit");
  return os.str();
}

}  // namespace

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
      os << "non-finite displacement or velocity at point " << i << " of level " << l << ", "
         << place_of(sim, l, i) << "; " << step_against_estimate(sim, l, i);
      return os.str();
    }
  if (!std::isfinite(internal_energy) || internal_energy > energy_bound) {
    const auto& in_force = sim.stable_step_in_force();
    std::ostringstream os;
    os.precision(4);
    os << "internal energy " << internal_energy << " J exceeds the bound " << energy_bound
       << " J (time.divergence.energy_factor x 1/2 V (lambda+2mu)); the step " << sim.step()
       << " s against the stable step estimate in force " << in_force.dt << " s";
    if (in_force.level >= 0)
      os << " (point " << in_force.point << " of level " << in_force.level << ", "
         << place_of(sim, in_force.level, in_force.point) << ")";
    // What to change depends on which side of the estimate the step was.
    if (sim.step() > in_force.dt)
      os << "; the step is above it: raise time.substeps or omit it to have it computed";
    else
      os << "; the step is within it: a large deformation, inverted tets or a sudden load";
    if (!sim.semi_implicit()) os << ", or use time.integrator: semi_implicit";
    return os.str();
  }
  return std::nullopt;
}

}  // namespace mrsim
