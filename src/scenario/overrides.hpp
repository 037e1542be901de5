#pragma once
// `--set key.path=value` overrides from the command line, applied to the document before
// validation so that an override is checked exactly like the file.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scenario/source_map.hpp"

namespace mrsim::scenario {

/// Applies each override in order. The path is dotted keys, with list indices as numbers
/// (`object.levels.0.mesh`); missing mappings on the way are created, an index equal to the
/// list's length appends. The value is read as YAML (`gravity=[0,0,0]`, `model=cauchy`).
/// Every value set is recorded in `positions` with origin "--set key.path=value", so later
/// errors about it name the override. Throws InputError for a malformed override.
void apply_overrides(nlohmann::json& document, SourceMap& positions,
                     const std::vector<std::string>& overrides);

}  // namespace mrsim::scenario
