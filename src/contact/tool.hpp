#pragma once
// A rigid tool driven along a trajectory (scenario `tool` / `tools`, method.md §6.2).
#include <string>

#include "contact/tool_shape.hpp"
#include "contact/tool_trajectory.hpp"

namespace mrsim {

/// Penalty contact (method.md §6.2 point 3): on every skin vertex inside the tool, a pressure
/// stiffness × depth − damping × (normal velocity of the skin relative to the tool), never
/// pulling, times the vertex's area, along the tool's outward normal.
struct ContactLaw {
  double stiffness = 0;  // Pa/m (N/m³); 0: automatic, per skin vertex (skin_contact.hpp)
  double damping = 0;    // Pa·s/m (N·s/m³)
};

struct Tool {
  std::string name;
  ToolShape shape;
  ToolTrajectory trajectory;
  ContactLaw contact;
};

}  // namespace mrsim
