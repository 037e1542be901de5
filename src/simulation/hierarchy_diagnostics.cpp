#include "simulation/hierarchy_diagnostics.hpp"

#include <algorithm>

#include "hierarchy/tet_shares.hpp"
#include "physics/internal_force.hpp"
#include "physics/stress.hpp"

namespace mrsim {

namespace {

double level_elastic_energy(const HierarchicalSimulation& sim, int l) {
  const LevelModel& m = sim.model(l);
  const auto& active = sim.lists().active(l);
  if (active.empty()) return 0;
  // The force pass's own list when it keeps one (the same sorted tets), else found here.
  std::vector<int> found;
  const std::vector<int>* live = sim.live_tets(l);
  if (!live) {
    std::vector<unsigned char> mark(m.num_tets(), 0);
    live_tets(m, IndexSet::of(active), mark, found);
    live = &found;
  }
  const std::vector<int>& tets = *live;
  const Vec3* u = sim.state(l).u.data();
  double e = 0;
  for (std::size_t k = 0; k < tets.size(); ++k) {
    if (k + kTetPrefetchAhead < tets.size()) prefetch_tet(m.geo, tets[k + kTetPrefetchAhead]);
    const int t = tets[k];
    const Mat3 G = tet_gradient(m.geo.grad[t], m.geo.tets[t], u);
    const Mat3 E = m.law.strain == StrainMeasure::GreenLagrange ? green_strain(G) : cauchy_strain(G);
    e += m.geo.volume[t] * energy_density(E, m.law, m.geo.scales_of(t, m.law.scales)) *
         active_share(sim.hierarchy(), l, m.geo.tets[t]);
  }
  return e;
}

}  // namespace

Energies hierarchy_energies(const HierarchicalSimulation& sim) {
  Energies e;
  double mass = 0;
  Vec3 momentum = Vec3::Zero();
  for (int l = 0; l < sim.num_levels(); ++l) {
    const auto& in = sim.inertia(l);  // the masses the integrator uses
    const auto& v = sim.state(l).v;
    for (int p : sim.lists().active(l)) {
      e.kinetic += 0.5 * in[p].mass * v[p].squaredNorm();
      mass += in[p].mass;
      momentum += in[p].mass * v[p];
    }
    e.elastic += level_elastic_energy(sim, l);
  }
  const Vec3 vcm = mass > 0 ? Vec3(momentum / mass) : Vec3::Zero();
  for (int l = 0; l < sim.num_levels(); ++l)
    for (int p : sim.lists().active(l))
      e.internal_kinetic += 0.5 * sim.inertia(l)[p].mass * (sim.state(l).v[p] - vcm).squaredNorm();
  return e;
}

Vec3 support_reaction(const HierarchicalSimulation& sim) {
  Vec3 r = -sim.held_by_support();
  for (int l = 0; l < sim.num_levels(); ++l)
    for (int p : sim.lists().active(l))
      if (!sim.state(l).free_point[p]) r -= sim.state(l).f[p];
  return r;
}

double max_active_displacement(const HierarchicalSimulation& sim) {
  double d = 0;
  for (int l = 0; l < sim.num_levels(); ++l)
    for (int p : sim.lists().active(l)) d = std::max(d, sim.state(l).u[p].norm());
  return d;
}

}  // namespace mrsim
