#include "scenario/scenario_builder.hpp"

namespace mrsim::scenario {

namespace {

using nlohmann::json;

Vec3 vec3(const json& v) { return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()}; }

std::filesystem::path file_path(const json& written_path, const std::filesystem::path& source) {
  const std::filesystem::path written = written_path.get<std::string>();
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
  if (name == "newton_cotes") return IntegratorKind::NewtonCotes;
  return IntegratorKind::ModifiedEuler;
}

TimeSpec time_spec(const json& t) {
  TimeSpec spec;
  spec.integrator = integrator(t["integrator"]);
  spec.frame_dt = t["frame_dt"].get<double>();
  spec.substeps = t.contains("substeps") ? t["substeps"].get<int>() : 0;
  spec.courant = t["courant"].get<double>();
  spec.adapt_substeps = t["adapt_substeps"].get<bool>();
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
  spec.calm_frames = a["calm_frames"].get<int>();
  spec.contact_refine = a["contact_refine"].get<bool>();
  spec.predict = a["predict"].get<bool>();
  spec.split_checks = a["split_checks"].get<int>();
  spec.coupling = a["coupling"] == "force"               ? Coupling::Force
                  : a["coupling"] == "energy_consistent" ? Coupling::EnergyConsistent
                                                         : Coupling::Energy;
  return spec;
}

KeyframeSpec keyframe(const json& k) {
  KeyframeSpec spec;
  spec.t = k["t"].get<double>();
  spec.position = vec3(k["position"]);
  if (k.contains("orientation"))
    for (int i = 0; i < 4; ++i) spec.orientation[i] = k["orientation"][i].get<double>();
  return spec;
}

ToolSpec tool_spec(const json& t, std::size_t index, const std::filesystem::path& source) {
  ToolSpec spec;
  spec.name = t.contains("name") ? t["name"].get<std::string>()
                                 : index == 0 ? "tool" : "tool_" + std::to_string(index);
  const json& shape = t["shape"];
  spec.shape = shape.begin().key();  // the schema allows exactly one key
  const json& size = shape.begin().value();
  spec.radius = size["radius"].get<double>();
  spec.length = size.contains("length") ? size["length"].get<double>() : 0.0;
  const json& trajectory = t["trajectory"];
  if (trajectory.is_object())
    spec.csv = file_path(trajectory["csv"], source);
  else
    for (const json& k : trajectory) spec.keyframes.push_back(keyframe(k));
  spec.smooth = t["interpolation"] == "smooth";
  const json& stiffness = t["contact"]["stiffness"];
  spec.stiffness = stiffness.is_number() ? stiffness.get<double>() : 0.0;  // 0: "auto"
  spec.damping = t["contact"]["damping"].get<double>();
  return spec;
}

// `tool` is a list of one.
std::vector<ToolSpec> tool_specs(const json& resolved, const std::filesystem::path& source) {
  std::vector<ToolSpec> tools;
  if (resolved.contains("tool")) tools.push_back(tool_spec(resolved["tool"], 0, source));
  for (const json& t : resolved["tools"]) tools.push_back(tool_spec(t, tools.size(), source));
  return tools;
}

FrameCompression frame_compression(const std::string& name) {
  if (name == "zlib") return FrameCompression::Zlib;
  if (name == "none") return FrameCompression::None;
  return FrameCompression::Lz4;  // the schema allows nothing else
}

OutputSpec output_spec(const json& o) {
  return {o["dir"].get<std::string>(), o["every"].get<int>(), o["vtk"].get<bool>(),
          o["checkpoint_every"].get<int>(), frame_compression(o["compression"].get<std::string>())};
}

}  // namespace

Scenario build_scenario(const json& resolved, const std::filesystem::path& source) {
  Scenario s;
  s.name = resolved["name"].get<std::string>();
  s.source = source;
  for (const auto& level : resolved["object"]["levels"])
    s.levels.push_back({file_path(level["mesh"], source)});
  s.units = resolved["object"]["units"] == "mm" ? LengthUnit::Millimetre : LengthUnit::Metre;
  s.skin_units = s.units;
  const std::string calibration = resolved["object"]["calibration"];
  s.calibration = calibration == "orthotropic" ? CalibrationKind::Orthotropic
                  : calibration == "per_tet"   ? CalibrationKind::PerTet
                                               : CalibrationKind::None;
  if (resolved["object"].contains("skin")) {
    const json& skin = resolved["object"]["skin"];
    if (skin.contains("surface")) s.skin = file_path(skin["surface"], source);
    if (skin.contains("units"))
      s.skin_units = skin["units"] == "mm" ? LengthUnit::Millimetre : LengthUnit::Metre;
  }
  s.material = material(resolved["material"]);
  for (const auto& f : resolved["fixed"]) s.fixed.push_back(fixed_region(f));
  for (const auto& l : resolved["loads"]) s.loads.push_back(load_spec(l));
  s.tools = tool_specs(resolved, source);
  s.gravity = vec3(resolved["gravity"]);
  s.initial = {vec3(resolved["initial"]["velocity"]),
               vec3(resolved["initial"]["angular_velocity"])};
  s.time = time_spec(resolved["time"]);
  s.space = space_spec(resolved["adaptivity"]["space"]);
  s.time_levels = {resolved["adaptivity"]["time"]["enabled"].get<bool>(),
                   resolved["adaptivity"]["time"]["velocity_change"].get<double>()};
  s.budget = {resolved["adaptivity"]["budget"]["realtime"].get<bool>(),
              resolved["adaptivity"]["budget"]["fraction"].get<double>()};
  s.output = output_spec(resolved["output"]);
  s.resolved = resolved;
  return s;
}

}  // namespace mrsim::scenario
