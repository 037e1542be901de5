#pragma once
// Validation of a scenario document against schemas/scenario.schema.json with valijson,
// reported as "file:line:col: key.path: message" lines.
#include <nlohmann/json.hpp>
#include <vector>

#include "scenario/issues.hpp"
#include "scenario/source_map.hpp"

namespace mrsim::scenario {

/// The document's problems against the schema; empty when it is valid.
std::vector<Issue> schema_issues(const nlohmann::json& document);

/// Throws InputError listing every problem, each with the place it came from.
void validate_against_schema(const nlohmann::json& document, const SourceMap& positions);

}  // namespace mrsim::scenario
