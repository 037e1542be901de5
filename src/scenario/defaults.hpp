#pragma once
// Filling in the schema's defaults, so that the resolved scenario states every value the
// simulation uses (and logs it).
#include <nlohmann/json.hpp>

namespace mrsim::scenario {

/// Adds every absent property that has a `default` in the scenario schema, recursively. An absent
/// mapping is created when something inside it has a default (e.g. `time` or
/// `output`), so `time: {}` and no `time` at all resolve alike. Expects a valid document.
void inject_defaults(nlohmann::json& document);

}  // namespace mrsim::scenario
