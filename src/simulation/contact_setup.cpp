#include "simulation/contact_setup.hpp"

#include "core/error.hpp"
#include "meshing/surface_readers.hpp"

namespace mrsim {

namespace {

ToolShape tool_shape(const ToolSpec& spec) {
  ToolShape shape;
  shape.kind = spec.shape == "capsule"         ? ToolShapeKind::Capsule
               : spec.shape == "flat_cylinder" ? ToolShapeKind::FlatCylinder
                                               : ToolShapeKind::Sphere;
  shape.radius = spec.radius;
  shape.length = spec.length;
  return shape;
}

std::vector<Keyframe> keyframes(const ToolSpec& spec, const std::string& key) {
  if (!spec.csv.empty()) {
    try {
      return read_trajectory_csv(spec.csv);
    } catch (const InputError& e) {
      throw InputError(key + ".trajectory.csv: " + e.what());
    }
  }
  std::vector<Keyframe> keys;
  for (const KeyframeSpec& k : spec.keyframes) {
    const auto& q = k.orientation;
    keys.push_back({k.t, k.position, Quat(q[0], q[1], q[2], q[3])});
  }
  return keys;
}

// "tool" when written as `tool`, "tools[k]" otherwise: the key path a user can find.
std::string tool_key(const Scenario& sc, std::size_t k) {
  return sc.resolved.contains("tool") ? "tool" : "tools[" + std::to_string(k) + "]";
}

}  // namespace

Skin scenario_skin(const Scenario& sc, const TetMesh& finest) {
  if (sc.skin.empty()) return boundary_skin(finest);
  SurfaceMesh surface = read_surface(sc.skin);
  weld_identical_points(surface);
  if (surface.triangles.empty())
    throw InputError("object.skin.surface: " + sc.skin.string() + " has no triangle");
  if (sc.skin_units == LengthUnit::Millimetre) scale_surface(surface, 1e-3);
  return surface_skin(std::move(surface.points), std::move(surface.triangles));
}

std::vector<Tool> scenario_tools(const Scenario& sc) {
  std::vector<Tool> tools;
  for (std::size_t k = 0; k < sc.tools.size(); ++k) {
    const ToolSpec& spec = sc.tools[k];
    Tool tool;
    tool.name = spec.name;
    tool.shape = tool_shape(spec);
    tool.trajectory = ToolTrajectory(keyframes(spec, tool_key(sc, k)),
                                     spec.smooth ? Interpolation::Smooth : Interpolation::Linear,
                                     tool_key(sc, k) + ".trajectory");
    tool.contact = {spec.stiffness, spec.damping};
    tools.push_back(std::move(tool));
  }
  return tools;
}

}  // namespace mrsim
