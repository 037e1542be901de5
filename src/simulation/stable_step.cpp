#include "simulation/stable_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "contact/contact_bound.hpp"
#include "contact/skin_binding.hpp"
#include "contact/tool_shape.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "physics/level_model.hpp"
#include "simulation/contact_setup.hpp"
#include "simulation/level_setup_from_scenario.hpp"
#include "simulation/result_cache.hpp"
#include "simulation/spectrum_cache.hpp"
#include "time/steps_per_frame.hpp"

namespace mrsim {

namespace {

// The contact bound of the points of the finest level that may become active, which moves the
// skin under a tool (adaptivity refines ahead of contact; without adaptivity that is level 0).
// The run re-reads it every frame from the skin vertices near the tools and the levels moving
// them (HierarchicalSimulation::stable_step_in_force).
void add_tool_contact(const Scenario& sc, const std::vector<const TetMesh*>& meshes,
                      const MaterialLaw& law, const Skin* given,
                      std::vector<std::vector<PointInertia>>& star) {
  if (sc.tools.empty()) return;
  // The skin of the last level that may become active: the run's (given) when that is the
  // finest level or the skin is a surface file, else that level's boundary.
  const int l = static_cast<int>(star.size()) - 1;
  const bool usable = given && (given->point.empty() || l + 1 == static_cast<int>(meshes.size()));
  const Skin own = usable ? Skin{} : scenario_skin(sc, *meshes[l]);
  const Skin& skin = usable ? *given : own;
  const std::vector<Tool> tools = scenario_tools(sc);
  const SkinPenalty penalty = skin_penalty(skin, tools, law.lambda + 2 * law.mu);
  const std::vector<int> reachable = reachable_skin(skin, tools, sc.time.duration, sc.time.frame_dt);
  // The level's own boundary: each vertex is a point of the level, no search needed.
  const bool on_points = !skin.point.empty();
  const SkinBinding binding = on_points ? SkinBinding{} : bind_skin(skin, {meshes[l]});
  add_contact_bounds(
      penalty, reachable,
      [&](int s, std::vector<ActiveTerm>& row) {
        if (on_points) {
          row.push_back({l, skin.point[s], 1.0});
          return;
        }
        const Tet& t = meshes[l]->tets[binding.tet[0][s]];
        for (int k = 0; k < 4; ++k) row.push_back({l, t[k], binding.bary[0][s][k]});
      },
      star);
}

// What sets the estimate at a point: the term whose removal would lengthen it most.
std::string cause_at(const PointInertia& with_contact, const PointInertia& own, bool semi,
                     double edge) {
  const double dt = stable_step_of(with_contact, semi);
  PointInertia undamped = own;
  undamped.damping = 0;
  const double elastic = stable_step_of(undamped, semi);
  const double no_contact = stable_step_of(own, semi);
  std::ostringstream os;
  os.precision(3);
  if (no_contact > 1.5 * dt)
    os << "the tools' contact penalty stiffness (the step without it would be " << no_contact
       << " s; lower tools[].contact.stiffness)";
  else if (elastic > 1.5 * no_contact)
    os << "the damping material.damping phi/psi (undamped the step would be " << elastic << " s)";
  else
    os << "the cells: shortest edge " << edge << " m at this point, P-wave speed";
  return os.str();
}

}  // namespace

double shortest_edge(const TetMesh& mesh) {
  double h2 = std::numeric_limits<double>::infinity();
  for (const Tet& t : mesh.tets)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        h2 = std::min(h2, (mesh.points[t[a]] - mesh.points[t[b]]).squaredNorm());
  return std::sqrt(h2);
}

namespace {

// Level l's model for the scenario's integrator, from the spectrum cache when it has it, and
// prepared for semi-implicit time levels when the scenario runs them.
LevelModel scenario_level_model(const Scenario& sc, const TetMesh& mesh, const LevelLaws& laws,
                                int l, bool* reused = nullptr) {
  const bool semi = is_semi_implicit(sc.time.integrator);
  LevelModel m = cached_level_model(mesh, laws.laws[l], semi, laws.held[l], reused);
  if (semi && sc.time_levels.enabled) prepare_semi_implicit_time_levels(m);
  return m;
}

}  // namespace

std::vector<LevelModel> level_models(const Scenario& sc, const std::vector<const TetMesh*>& meshes,
                                     const LevelLaws& laws) {
  std::vector<LevelModel> models;
  models.reserve(meshes.size());
  int reused = 0;
  for (size_t l = 0; l < meshes.size(); ++l) {
    bool hit = false;
    models.push_back(scenario_level_model(sc, *meshes[l], laws, static_cast<int>(l), &hit));
    reused += hit;
  }
  if (reused > 0)
    info("the spectra of " + std::to_string(reused) + " of " + std::to_string(meshes.size()) +
         " levels: reused from " + result_cache_dir("spectra").string());
  return models;
}

StableStep stable_step(const Scenario& sc, const std::vector<const TetMesh*>& meshes,
                       const LevelLaws* laws,
                       const std::vector<LevelModel>* built, const Skin* skin) {
  const MaterialLaw law = material_law(sc.material);
  const LevelLaws computed = laws ? LevelLaws{} : level_laws(sc, meshes);
  if (!laws) laws = &computed;
  const bool semi = is_semi_implicit(sc.time.integrator);
  int last = 0;
  if (sc.space.enabled)
    last = sc.space.max_level >= 0 ? std::min<int>(sc.space.max_level, meshes.size() - 1)
                                   : static_cast<int>(meshes.size()) - 1;
  std::vector<LevelModel> own_models;
  if (!built)
    for (int l = 0; l <= last; ++l)
      own_models.push_back(scenario_level_model(sc, *meshes[l], *laws, l));
  const std::vector<LevelModel>& models = built ? *built : own_models;
  std::vector<std::vector<PointInertia>> star;
  for (int l = 0; l <= last; ++l) star.push_back(models[l].star);
  auto own = [&](int l, int p) {  // without contact
    const PointInertia& s = models[l].star[p];
    return calibrated(s, models[l], semi, sc.time_levels.enabled, 0.0, 0.0, p);
  };
  // One global step: calibrated by the level's spectrum; time levels: proven stiffness bounds,
  // calibrated damping.
  for (int l = 0; l <= last; ++l)
    for (int p = 0; p < static_cast<int>(star[l].size()); ++p) star[l][p] = own(l, p);
  add_tool_contact(sc, meshes, law, skin, star);
  StableStep best{std::numeric_limits<double>::infinity(), 0, 0, ""};
  for (int l = 0; l <= last; ++l)
    for (int p = 0; p < static_cast<int>(star[l].size()); ++p) {
      if (is_held(models[l], p)) continue;  // never moves (the run's step skips it too)
      const double dt = stable_step_of(star[l][p], semi);
      if (dt < best.dt) best = {dt, l, p, ""};
    }
  if (is_two_step(sc.time.integrator)) best.dt *= kTwoStepMidpointShare;
  if (std::isfinite(best.dt))
    best.cause = cause_at(star[best.level][best.point], own(best.level, best.point), semi,
                          models[best.level].min_edge[best.point]);
  return best;
}

long long computed_substeps(double frame_dt, double allowed, bool time_levels, int parts) {
  if (time_levels) {
    // The time levels halve the step (frame_dt / 2^k): a power of two, with two finer levels
    // than stability needs for the velocity-change rule (method.md §5.2).
    long long n = 1;
    while (n <= kMaxSubsteps && frame_dt / n > allowed) n *= 2;
    return std::min<long long>(4 * n, kMaxSubsteps);
  }
  // One global step: the fewest steps that fit, so the step is the largest the estimate
  // allows (a power of two took up to twice the steps needed: liver_probe 128 for 103), a
  // multiple of the frame's split checks so that its parts are equal.
  return fewest_steps(frame_dt, allowed, parts, kMaxSubsteps);
}

Scenario with_stable_substeps(const Scenario& sc, const std::vector<const TetMesh*>& meshes,
                              const LevelLaws* laws,
                              const std::vector<LevelModel>* models, const Skin* skin) {
  const StableStep stable = stable_step(sc, meshes, laws, models, skin);
  const double allowed = sc.time.courant * stable.dt;
  const bool time_levels = sc.time_levels.enabled;
  std::ostringstream where;
  where.precision(4);
  where << "level " << stable.level << ", point " << stable.point << ": stable step estimate "
        << stable.dt << " s, set by " << stable.cause;
  std::ostringstream os;
  os.precision(4);
  if (is_two_step(sc.time.integrator) && material_law(sc.material).damped())
    warn(
        "time.integrator newton_cotes with material.damping: unstable at every step size (its "
        "parasitic solution grows like exp(gamma t / 2) with the damping rate gamma of the "
        "stiffest mode; docs/integrators.md); set phi = psi = 0 or use modified_euler");
  if (sc.time.courant > 1)
    warn("time.courant " + std::to_string(sc.time.courant) +
         " > 1: steps above the stable step estimate (for stability studies)");
  // More than the cap would never finish a frame (time.adapt_substeps would keep doubling).
  const double needed = sc.time.frame_dt / allowed * (time_levels ? 4 : 1);
  if (!(needed <= kMaxSubsteps) && (sc.time.substeps == 0 || sc.time.adapt_substeps)) {
    os << "time.substeps: the stable step needs " << needed << " steps per frame of "
       << sc.time.frame_dt << " s, more than the " << kMaxSubsteps << " mrsim allows ("
       << where.str() << (time_levels ? "; x4 for the time levels" : "")
       << "); check the mesh units (object.units), the material and the tools";
    throw InputError(os.str());
  }
  if (sc.time.substeps > 0) {
    const double dt = sc.time.frame_dt / sc.time.substeps;
    if (dt > allowed) {
      os << "time step " << dt << " s (frame_dt / substeps) exceeds time.courant x the stable "
         << "step estimate, " << allowed << " s (" << where.str() << "); raise time.substeps "
         << "to at least " << std::ceil(sc.time.frame_dt / allowed)
         << " or omit it to have it computed";
      warn(os.str());
    }
    return sc;
  }
  const long long substeps = computed_substeps(sc.time.frame_dt, allowed, time_levels,
                                               sc.space.enabled ? sc.space.split_checks : 1);
  Scenario out = sc;
  out.time.substeps = static_cast<int>(substeps);
  out.resolved["time"]["substeps"] = out.time.substeps;
  os << "time.substeps computed: " << substeps << " (step " << sc.time.frame_dt / substeps
     << " s; time.courant " << sc.time.courant << " x " << where.str()
     << (time_levels ? "; x4 for the finer time levels" : "") << ")";
  info(os.str());
  return out;
}

}  // namespace mrsim
