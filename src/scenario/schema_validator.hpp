#pragma once
// Validation of a scenario document against schemas/scenario.schema.json with valijson,
// reported as "file:line:col: key.path: message" lines.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scenario/issues.hpp"
#include "scenario/source_map.hpp"

namespace mrsim::scenario {

/// The JSON pointer of the place valijson names as {"<root>", "[material]", "[lambda]", "[0]"}.
/// Keys may contain dots and items look like "[0]" too, so the document decides what each
/// token is (valid as far as the document goes; the rest is dropped).
std::string valijson_context_pointer(const std::vector<std::string>& context,
                                     const nlohmann::json& document);

/// The document's problems against the schema; empty when it is valid.
std::vector<Issue> schema_issues(const nlohmann::json& document);

/// Throws InputError listing every problem, each with the place it came from.
void validate_against_schema(const nlohmann::json& document, const SourceMap& positions);

}  // namespace mrsim::scenario
