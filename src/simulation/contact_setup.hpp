#pragma once
// Translation of the scenario's tools and skin into the contact model (contact/): shapes,
// trajectories (keyframes or a device recording), the penalty law, and the skin (the finest
// level's boundary or a separate surface file).
#include <vector>

#include "contact/skin.hpp"
#include "contact/tool.hpp"
#include "scenario/scenario.hpp"

namespace mrsim {

/// The skin the tools touch: the scenario's surface file (in object.skin.units) or the boundary of
/// the finest level. Throws InputError on an unreadable or empty surface.
Skin scenario_skin(const Scenario& sc, const TetMesh& finest);

/// The tools (reads CSV trajectories; throws InputError naming the tool on a bad file).
std::vector<Tool> scenario_tools(const Scenario& sc);

}  // namespace mrsim
