#include "scenario/scenario_builder.hpp"

namespace mrsim::scenario {

namespace {

using nlohmann::json;

Vec3 vec3(const json& v) { return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()}; }

std::filesystem::path mesh_path(const json& level, const std::filesystem::path& source) {
  const std::filesystem::path written = level["mesh"].get<std::string>();
  const auto folder = std::filesystem::absolute(source).parent_path();
  return (folder / written).lexically_normal();  // an absolute `written` replaces `folder`
}

MaterialSpec material(const json& m) {
  MaterialSpec spec;
  spec.model = m["model"] == "cauchy" ? StrainModel::Cauchy : StrainModel::GreenLagrange;
  const json& derived = m["derived"];
  spec.lambda = derived["lambda"].get<double>();
  spec.mu = derived["mu"].get<double>();
  spec.youngs_modulus = derived["youngs_modulus"].get<double>();
  spec.poisson = derived["poisson_ratio"].get<double>();
  spec.density = m["density"].get<double>();
  spec.phi = m["damping"]["phi"].get<double>();
  spec.psi = m["damping"]["psi"].get<double>();
  return spec;
}

FixedRegion fixed_region(const json& f) {
  FixedRegion region;
  if (f.contains("box")) {
    region.kind = FixedRegion::Kind::Box;
    region.min = vec3(f["box"]["min"]);
    region.max = vec3(f["box"]["max"]);
  } else if (f.contains("half_space")) {
    region.kind = FixedRegion::Kind::HalfSpace;
    region.point = vec3(f["half_space"]["point"]);
    region.normal = vec3(f["half_space"]["normal"]);
  } else {
    region.kind = FixedRegion::Kind::Ids;
    region.ids = f["ids"].get<std::vector<int>>();
  }
  region.level = f.contains("level") ? f["level"].get<int>() : -1;
  return region;
}

IntegratorKind integrator(const json& name) {
  if (name == "stoermer_verlet") return IntegratorKind::StoermerVerlet;
  if (name == "semi_implicit") return IntegratorKind::SemiImplicit;
  if (name == "semi_implicit_momentum") return IntegratorKind::SemiImplicitMomentum;
  return IntegratorKind::ModifiedEuler;
}

TimeSpec time_spec(const json& t) {
  TimeSpec spec;
  spec.integrator = integrator(t["integrator"]);
  spec.frame_dt = t["frame_dt"].get<double>();
  spec.substeps = t.contains("substeps") ? t["substeps"].get<int>() : 0;
  spec.courant = t["courant"].get<double>();
  spec.duration = t["duration"].get<double>();
  spec.divergence_energy_factor = t["divergence"]["energy_factor"].get<double>();
  return spec;
}

SurfaceLoadSpec load_spec(const json& l) {
  SurfaceLoadSpec spec;
  spec.min = vec3(l["box"]["min"]);
  spec.max = vec3(l["box"]["max"]);
  spec.force = vec3(l["force"]);
  spec.profile.clear();
  for (const json& p : l["profile"]) spec.profile.emplace_back(p[0].get<double>(), p[1].get<double>());
  return spec;
}

SpaceAdaptivitySpec space_spec(const json& a) {
  SpaceAdaptivitySpec spec;
  spec.enabled = a["enabled"].get<bool>();
  spec.refine_above = a["refine_above"].get<double>();
  spec.coarsen_below = a["coarsen_below"].get<double>();
  spec.max_level = a.contains("max_level") ? a["max_level"].get<int>() : -1;
  spec.max_active_points = a["max_active_points"].get<std::int64_t>();
  spec.min_dwell_frames = a["min_dwell_frames"].get<int>();
  spec.coupling = a["coupling"] == "force"               ? Coupling::Force
                  : a["coupling"] == "energy_consistent" ? Coupling::EnergyConsistent
                                                         : Coupling::Energy;
  return spec;
}

OutputSpec output_spec(const json& o) {
  return {o["dir"].get<std::string>(), o["every"].get<int>(), o["vtk"].get<bool>()};
}

}  // namespace

Scenario build_scenario(const json& resolved, const std::filesystem::path& source) {
  Scenario s;
  s.name = resolved["name"].get<std::string>();
  s.source = source;
  for (const auto& level : resolved["object"]["levels"])
    s.levels.push_back({mesh_path(level, source)});
  s.units = resolved["object"]["units"] == "mm" ? LengthUnit::Millimetre : LengthUnit::Metre;
  s.material = material(resolved["material"]);
  for (const auto& f : resolved["fixed"]) s.fixed.push_back(fixed_region(f));
  for (const auto& l : resolved["loads"]) s.loads.push_back(load_spec(l));
  s.gravity = vec3(resolved["gravity"]);
  s.initial = {vec3(resolved["initial"]["velocity"]),
               vec3(resolved["initial"]["angular_velocity"])};
  s.time = time_spec(resolved["time"]);
  s.space = space_spec(resolved["adaptivity"]["space"]);
  s.time_levels = {resolved["adaptivity"]["time"]["enabled"].get<bool>(),
                   resolved["adaptivity"]["time"]["velocity_change"].get<double>()};
  s.output = output_spec(resolved["output"]);
  s.resolved = resolved;
  return s;
}

}  // namespace mrsim::scenario
