#include "simulation/stable_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/log.hpp"
#include "simulation/level_setup_from_scenario.hpp"
#include "time/time_level_rules.hpp"

namespace mrsim {

double shortest_edge(const TetMesh& mesh) {
  double h2 = std::numeric_limits<double>::infinity();
  for (const Tet& t : mesh.tets)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        h2 = std::min(h2, (mesh.points[t[a]] - mesh.points[t[b]]).squaredNorm());
  return std::sqrt(h2);
}

StableStep stable_step(const Scenario& sc, const std::vector<const TetMesh*>& meshes) {
  const MaterialLaw law = material_law(sc.material);
  const bool semi_implicit = is_semi_implicit(sc.time.integrator);
  int last = 0;
  if (sc.space.enabled)
    last = sc.space.max_level >= 0 ? std::min<int>(sc.space.max_level, meshes.size() - 1)
                                   : static_cast<int>(meshes.size()) - 1;
  StableStep best{std::numeric_limits<double>::infinity(), 0};
  for (int l = 0; l <= last; ++l) {
    const double dt = courant_step(law, sc.time.courant, semi_implicit, shortest_edge(*meshes[l]));
    if (dt < best.dt) best = {dt, l};
  }
  return best;
}

Scenario with_stable_substeps(const Scenario& sc, const std::vector<const TetMesh*>& meshes) {
  const StableStep stable = stable_step(sc, meshes);
  std::ostringstream os;
  if (sc.time.substeps > 0) {
    const double dt = sc.time.frame_dt / sc.time.substeps;
    if (dt > stable.dt) {
      os << "level " << stable.level << ": time step " << dt
         << " s (frame_dt / substeps) exceeds the stable estimate " << stable.dt
         << " s (time.courant x shortest edge / P-wave speed"
         << (is_semi_implicit(sc.time.integrator) ? ", x2 for semi_implicit" : "")
         << "); raise time.substeps to at least " << std::ceil(sc.time.frame_dt / stable.dt)
         << " or omit it to have it computed";
      warn(os.str());
    }
    return sc;
  }
  int substeps = 1;
  while (sc.time.frame_dt / substeps > stable.dt && substeps < (1 << 30)) substeps *= 2;
  // Time levels: two finer levels than Courant needs, for the velocity-change rule (§5.2).
  const bool time_levels = sc.time_levels.enabled;
  if (time_levels) substeps = std::min(substeps * 4, 1 << 30);
  Scenario out = sc;
  out.time.substeps = substeps;
  out.resolved["time"]["substeps"] = substeps;
  os << "time.substeps computed: " << substeps << " (step " << sc.time.frame_dt / substeps
     << " s; stable estimate " << stable.dt << " s, set by level " << stable.level
     << (time_levels ? "; x4 for the finer time levels" : "") << ")";
  info(os.str());
  return out;
}

}  // namespace mrsim
