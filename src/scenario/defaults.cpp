#include "scenario/defaults.hpp"

#include "scenario/schema.hpp"

namespace mrsim::scenario {

namespace {

using nlohmann::json;

bool has_defaults_inside(const json& referring_node) {
  const json& node = resolve_ref(referring_node);
  if (!node.contains("properties")) return false;
  for (const auto& [key, child] : node["properties"].items())
    if (child.contains("default") || has_defaults_inside(child)) return true;
  return false;
}

// An object with required keys (a tool) exists only when the user writes it.
bool optional_object(const json& referring_node) {
  const json& node = resolve_ref(referring_node);
  return !node.contains("required") || node["required"].empty();
}

void fill(json& value, const json& referring_node) {
  const json& node = resolve_ref(referring_node);
  if (value.is_object() && node.contains("properties")) {
    for (const auto& [key, child] : node["properties"].items()) {
      if (!value.contains(key)) {
        // `default` sits on the referring node when the type comes from a $ref.
        if (child.contains("default"))
          value[key] = child["default"];
        else if (has_defaults_inside(child) && optional_object(child))
          value[key] = json::object();
        else
          continue;
      }
      fill(value[key], child);
    }
  }
  if (value.is_array() && node.contains("items") && node["items"].is_object())
    for (auto& item : value) fill(item, node["items"]);
}

}  // namespace

void inject_defaults(json& document) { fill(document, scenario_schema()); }

}  // namespace mrsim::scenario
