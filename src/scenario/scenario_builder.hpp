#pragma once
// The typed Scenario from a resolved document (schema-valid, defaults and derived constants
// in): the one place that knows how JSON keys map onto the struct fields.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "scenario/scenario.hpp"

namespace mrsim::scenario {

/// Mesh paths are made absolute against the folder of `source`; `resolved` is kept as is.
Scenario build_scenario(const nlohmann::json& resolved, const std::filesystem::path& source);

}  // namespace mrsim::scenario
