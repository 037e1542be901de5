#include "simulation/level_setup_from_scenario.hpp"

#include <algorithm>
#include <bit>
#include <sstream>

#include "core/log.hpp"
#include "simulation/calibration_cache.hpp"
#include "simulation/contact_setup.hpp"
#include "simulation/fixed_points.hpp"
#include "simulation/level_consistency.hpp"
#include "simulation/surface_load_distribution.hpp"

namespace mrsim {

MaterialLaw material_law(const MaterialSpec& spec) {
  MaterialLaw law;
  law.strain = spec.model;
  law.lambda = spec.lambda;
  law.mu = spec.mu;
  law.phi = spec.phi;
  law.psi = spec.psi;
  law.density = spec.density;
  return law;
}

namespace {

// "object.calibration: level 0 factors λ 1.72 xx 0.87 ...; alone vs the finest: sag x 1.00 ->
// 1.05 ..., f1 1.76 -> 1.05" (ratios before -> after the fit).
std::string calibration_line(int level, const LevelCalibration& c) {
  static const char* const kNames[7] = {"lambda", "xx", "yy", "zz", "yz", "xz", "xy"};
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(2);
  os << "object.calibration: level " << level << " factors";
  const std::array<double, 7> s = c.scales.components();
  for (int j = 0; j < 7; ++j) os << ' ' << kNames[j] << ' ' << s[j];
  os << "; alone vs the finest level (before -> after):";
  for (size_t d = 0; d < c.sag_after.size(); ++d)
    os << " sag " << "xyz"[d] << ' ' << c.sag_before[d] << " -> " << c.sag_after[d] << ',';
  for (size_t d = 0; d < c.peak_after.size() && !c.tet_tensors.empty(); ++d)
    os << " peak " << "xyz"[d] << ' ' << c.peak_before[d] << " -> " << c.peak_after[d] << ',';
  if (!c.frequency_after.empty())
    os << " f1 " << c.frequency_before[0] << " -> " << c.frequency_after[0];
  if (!c.tet_tensors.empty()) {
    const std::array<double, 2> range = c.tet_factor_range();
    os << "; per-tet factors " << range[0] << " to " << range[1];
  }
  if (!c.local_after.empty()) {
    auto range = [&os](const std::vector<double>& r) {
      const auto [low, high] = std::minmax_element(r.begin(), r.end());
      os << *low << '-' << *high;
    };
    os << "; local loads ";
    range(c.local_before);
    os << " -> ";
    range(c.local_after);
    os << (c.local_fitted ? " (fitted)" : " (not fitted: the level's sags, peaks or f1 would move)");
  }
  return os.str();
}

}  // namespace

LevelLaws level_laws(const Scenario& sc, const std::vector<const TetMesh*>& meshes) {
  LevelLaws out;
  const MaterialLaw law = material_law(sc.material);
  out.laws.assign(meshes.size(), law);
  out.held = select_fixed_points(meshes, sc.fixed);
  if (sc.calibration == CalibrationKind::None || meshes.size() < 2) return out;
  const std::filesystem::path cache = calibration_cache_dir();
  const std::string key = calibration_key(meshes, law, out.held, sc.calibration);
  if (auto cached = read_cached_calibration(cache, key, meshes)) {
    out.calibration = std::move(*cached);
    info("object.calibration: read from the cache " + cache.string() + " (key " + key + ")");
  } else {
    out.calibration = calibrate_levels(meshes, law, out.held, sc.calibration);
    write_cached_calibration(cache, key, out.calibration);
  }
  for (size_t l = 0; l < meshes.size(); ++l) {
    out.laws[l] = out.calibration[l].applied_to(law);
    if (l + 1 < meshes.size()) info(calibration_line(static_cast<int>(l), out.calibration[l]));
  }
  return out;
}

HierarchySetup hierarchy_setup(const Scenario& sc, const std::vector<const TetMesh*>& meshes,
                               const LevelLaws* laws, const Skin* skin) {
  check_level_consistency(sc, meshes);
  HierarchySetup s;
  s.law = material_law(sc.material);
  const LevelLaws computed = laws ? LevelLaws{} : level_laws(sc, meshes);
  if (!laws) laws = &computed;
  if (!laws->calibration.empty()) {
    s.level_laws = laws->laws;
    s.calibration = laws->calibration;
  }
  s.gravity = sc.gravity;
  s.integrator = sc.time.integrator;
  s.coupling = sc.space.coupling;
  s.dt = sc.time.frame_dt / sc.time.substeps;
  s.steps_per_frame = sc.time.substeps;
  s.adapt_step = sc.time.adapt_substeps && !sc.time_levels.enabled;
  s.courant = sc.time.courant;
  if (sc.time_levels.enabled) {
    TimeLevelRules rules;
    rules.frame_dt = sc.time.frame_dt;
    rules.max_level = std::countr_zero(static_cast<unsigned>(sc.time.substeps));
    rules.courant = sc.time.courant;
    rules.velocity_change = sc.time_levels.velocity_change;
    rules.semi_implicit = is_semi_implicit(sc.time.integrator);
    s.time_levels = rules;
  }
  s.fixed = laws->held;
  s.initial_velocity = sc.initial.velocity;
  s.initial_angular_velocity = sc.initial.angular_velocity;
  for (size_t k = 0; k < sc.loads.size(); ++k)
    s.loads.push_back(distribute_surface_load(*meshes.back(), sc.loads[k], k));
  if (!sc.tools.empty()) {
    s.tools = scenario_tools(sc);
    s.skin = skin ? *skin : scenario_skin(sc, *meshes.back());
  }
  return s;
}

SpaceAdaptivitySettings space_settings(const Scenario& sc) {
  SpaceAdaptivitySettings s;
  s.enabled = sc.space.enabled;
  s.refine_above = sc.space.refine_above;
  s.coarsen_below = sc.space.coarsen_below;
  if (sc.space.max_level >= 0) s.max_level = sc.space.max_level;
  s.max_active_points = sc.space.max_active_points;
  s.min_dwell_frames = sc.space.min_dwell_frames;
  s.calm_frames = sc.space.calm_frames;
  // One level finer per frame: look as many frames ahead as there are levels to go through.
  if (!sc.tools.empty() && sc.space.contact_refine)
    s.contact_lookahead = sc.time.frame_dt * static_cast<double>(sc.levels.size());
  if (sc.space.predict) {
    s.predict_horizon = sc.time.frame_dt;
    s.predict_window = sc.time.frame_dt * static_cast<double>(sc.levels.size());
  }
  s.gravity = sc.gravity;
  return s;
}

}  // namespace mrsim
