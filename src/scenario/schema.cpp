#include "scenario/schema.hpp"

#include <algorithm>
#include <charconv>

#include "scenario/json_path.hpp"

namespace mrsim::scenario {

namespace {

using nlohmann::json;

// The order of properties is only kept by nlohmann::ordered_json.
void collect_order(const nlohmann::ordered_json& node, std::vector<std::string>& order) {
  if (!node.is_object()) return;
  if (auto it = node.find("properties"); it != node.end() && it->is_object()) {
    for (const auto& [key, child] : it->items()) {
      if (std::find(order.begin(), order.end(), key) == order.end()) order.push_back(key);
      collect_order(child, order);
    }
  }
  if (auto it = node.find("items"); it != node.end()) collect_order(*it, order);
}

void collect_paths(const json& node, const std::string& prefix, std::vector<std::string>& paths) {
  const json& resolved = resolve_ref(node);
  if (!resolved.is_object()) return;
  if (auto it = resolved.find("properties"); it != resolved.end()) {
    for (const auto& [key, child] : it->items()) {
      const std::string path = prefix.empty() ? key : prefix + "." + key;
      paths.push_back(path);
      collect_paths(child, path, paths);
    }
  }
  if (auto it = resolved.find("items"); it != resolved.end())
    collect_paths(*it, prefix.empty() ? "N" : prefix + ".N", paths);
}

// The node of `token` under `resolved`: its own properties, or those of the one oneOf branch
// that declares it (a tool shape's sphere, capsule or flat_cylinder), so that a fault inside the
// chosen branch is described by its own keywords and not by valijson's text of every branch.
const json* property_node(const json& resolved, const std::string& token) {
  if (resolved.contains("properties") && resolved["properties"].contains(token))
    return &resolved["properties"][token];
  if (!resolved.contains("oneOf")) return nullptr;
  const json* found = nullptr;
  for (const json& branch : resolved["oneOf"]) {
    const json& b = resolve_ref(branch);
    if (!b.contains("properties") || !b["properties"].contains(token)) continue;
    if (found) return nullptr;  // declared by several branches: no single schema
    found = &b["properties"][token];
  }
  return found;
}

// The schema parsed once, in its own order; scenario_schema() converts it (a third of what a
// second parse of the text cost every run: both are needed by every run).
const nlohmann::ordered_json& ordered_schema() {
  static const nlohmann::ordered_json schema =
      nlohmann::ordered_json::parse(embedded_schema_text());
  return schema;
}

}  // namespace

const json& scenario_schema() {
  static const json schema = json(ordered_schema());
  return schema;
}

const json& resolve_ref(const json& node) {
  const json* current = &node;
  // A bounded loop: a chain of references longer than this would be a broken schema.
  for (int hops = 0; hops < 8 && current->is_object() && current->contains("$ref"); ++hops) {
    const auto ref = (*current)["$ref"].get<std::string>();
    if (ref.rfind("#", 0) != 0) break;
    current = &scenario_schema().at(json::json_pointer(ref.substr(1)));
  }
  return *current;
}

const json* schema_at(const std::string& pointer, const json& document) {
  const json* node = &scenario_schema();
  const json* value = &document;
  for (const auto& token : pointer_tokens(pointer)) {
    const json& resolved = resolve_ref(*node);
    if (value->is_array() && resolved.contains("items")) {
      std::size_t index = 0;
      const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), index);
      if (error != std::errc{} || end != token.data() + token.size() || index >= value->size())
        return nullptr;
      node = &resolved["items"];
      value = &(*value)[index];
    } else if (const json* child = value->is_object() && value->contains(token)
                                       ? property_node(resolved, token)
                                       : nullptr) {
      node = child;
      value = &value->at(token);
    } else {
      return nullptr;
    }
  }
  return node;
}

const std::vector<std::string>& property_order() {
  static const std::vector<std::string> order = [] {
    std::vector<std::string> keys;
    collect_order(ordered_schema(), keys);
    return keys;
  }();
  return order;
}

const std::vector<std::string>& property_paths() {
  static const std::vector<std::string> paths = [] {
    std::vector<std::string> all;
    collect_paths(scenario_schema(), "", all);
    return all;
  }();
  return paths;
}

}  // namespace mrsim::scenario
