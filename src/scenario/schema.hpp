#pragma once
// The scenario schema (schemas/scenario.schema.json, embedded at build time) and the few
// ways of walking it that messages, defaults and output need. The walks understand the
// subset of JSON Schema the file uses: properties, items, local $ref to #/definitions.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace mrsim::scenario {

/// The schema file's text as it was at build time.
std::string_view embedded_schema_text();

/// The parsed schema (parsed once).
const nlohmann::json& scenario_schema();

/// Follows a local "$ref" ("#/definitions/x"); other nodes are returned as they are.
/// Annotations beside a "$ref" (description, default) stay on the referring node.
const nlohmann::json& resolve_ref(const nlohmann::json& node);

/// The schema node of a document value, found by following `properties` and `items` along
/// the pointer; nullptr where the schema does not describe the place (e.g. an unknown key).
const nlohmann::json* schema_at(const std::string& pointer, const nlohmann::json& document);

/// Property names in the order the schema lists them (first appearance, depth first):
/// the resolved YAML uses it so that `name` comes first and related keys stay together.
const std::vector<std::string>& property_order();

/// Dotted paths ("material.lambda") of every property the schema defines, list items
/// written as "N": used to say where a key misplaced at another level belongs.
const std::vector<std::string>& property_paths();

}  // namespace mrsim::scenario
