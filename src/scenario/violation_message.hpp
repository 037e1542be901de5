#pragma once
// Human messages for schema violations. valijson decides *whether* and *where* a document is
// invalid; its texts ("Failed to validate against schema associated with property name ...")
// do not help a user, so the message is rebuilt here from the schema node at that place and
// the offending value: "must be >= 0 (got -5)", "unknown key; did you mean 'every'?".
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scenario/issues.hpp"

namespace mrsim::scenario {

/// Problems of `value` (at `pointer`) against the keywords of schema `node` itself, not
/// against those of its children. Empty when the node's own keywords are satisfied.
std::vector<Issue> describe_violations(const nlohmann::json& value, const nlohmann::json& node,
                                       const std::string& pointer);

/// "'abc'", "-5", "true", "a list of 2 items", "a mapping": a value as messages show it.
std::string describe_value(const nlohmann::json& value);

}  // namespace mrsim::scenario
