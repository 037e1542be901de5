#include "scenario/violation_message.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <regex>

#include "scenario/did_you_mean.hpp"
#include "scenario/json_path.hpp"
#include "scenario/schema.hpp"

namespace mrsim::scenario {

namespace {

using nlohmann::json;
using Problem = std::optional<std::string>;

bool has_type(const json& value, const std::string& type) {
  if (type == "number") return value.is_number();
  if (type == "integer") return value.is_number_integer();
  if (type == "string") return value.is_string();
  if (type == "boolean") return value.is_boolean();
  if (type == "array") return value.is_array();
  if (type == "object") return value.is_object();
  return type == "null" && value.is_null();
}

std::string type_noun(const std::string& type) {
  if (type == "integer") return "an integer";
  if (type == "boolean") return "true or false";
  if (type == "array") return "a list";
  if (type == "object") return "a mapping";
  return "a " + type;
}

Problem type_problem(const json& value, const json& node) {
  if (!node.contains("type")) return std::nullopt;
  const json& type = node["type"];
  const auto types = type.is_array() ? type.get<std::vector<std::string>>()
                                     : std::vector<std::string>{type.get<std::string>()};
  if (std::any_of(types.begin(), types.end(), [&](auto& t) { return has_type(value, t); }))
    return std::nullopt;
  std::string nouns;
  for (const auto& t : types) nouns += (nouns.empty() ? "" : " or ") + type_noun(t);
  return "must be " + nouns + " (got " + describe_value(value) + ")";
}

Problem enum_problem(const json& value, const json& node) {
  if (!node.contains("enum")) return std::nullopt;
  const json& allowed = node["enum"];
  if (std::find(allowed.begin(), allowed.end(), value) != allowed.end()) return std::nullopt;
  std::string list;
  std::vector<std::string> names;
  for (const auto& a : allowed) {
    list += (list.empty() ? "" : ", ") + describe_value(a);
    if (a.is_string()) names.push_back(a.get<std::string>());
  }
  std::string message = "must be one of " + list + " (got " + describe_value(value) + ")";
  if (value.is_string())
    if (auto guess = closest_match(value.get<std::string>(), names))
      message += "; did you mean '" + *guess + "'?";
  return message;
}

Problem bound_problem(const json& value, const json& node) {
  if (!value.is_number()) return std::nullopt;
  const double x = value.get<double>();
  const std::string got = " (got " + describe_value(value) + ")";
  auto bound = [&](const char* keyword) -> std::optional<double> {
    if (!node.contains(keyword)) return std::nullopt;
    return node[keyword].get<double>();
  };
  if (auto b = bound("minimum"); b && !(x >= *b))
    return "must be >= " + node["minimum"].dump() + got;
  if (auto b = bound("exclusiveMinimum"); b && !(x > *b))
    return "must be > " + node["exclusiveMinimum"].dump() + got;
  if (auto b = bound("maximum"); b && !(x <= *b))
    return "must be <= " + node["maximum"].dump() + got;
  if (auto b = bound("exclusiveMaximum"); b && !(x < *b))
    return "must be < " + node["exclusiveMaximum"].dump() + got;
  return std::nullopt;
}

std::string items_text(std::size_t n) { return std::to_string(n) + (n == 1 ? " item" : " items"); }

Problem size_problem(const json& value, const json& node) {
  if (!value.is_array()) return std::nullopt;
  const std::size_t n = value.size();
  const std::size_t lo = node.value("minItems", std::size_t{0});
  const std::size_t hi = node.value("maxItems", std::numeric_limits<std::size_t>::max());
  const std::string got = " (got " + std::to_string(n) + ")";
  if (lo == hi && n != lo) return "must have exactly " + items_text(lo) + got;
  if (n < lo) return "must have at least " + items_text(lo) + got;
  if (n > hi) return "must have at most " + items_text(hi) + got;
  return std::nullopt;
}

Problem string_problem(const json& value, const json& node) {
  if (!value.is_string()) return std::nullopt;
  const auto text = value.get<std::string>();
  if (text.size() < node.value("minLength", std::size_t{0})) return "must not be empty";
  if (node.contains("pattern")) {
    const auto pattern = node["pattern"].get<std::string>();
    if (!std::regex_search(text, std::regex(pattern)))
      return "must match the pattern " + pattern + " (got " + describe_value(value) + ")";
  }
  return std::nullopt;
}

std::vector<std::string> property_names(const json& node) {
  std::vector<std::string> names;
  if (node.contains("properties"))
    for (const auto& [key, child] : node["properties"].items()) names.push_back(key);
  return names;
}

// Where a key that is unknown here belongs, if the schema defines it elsewhere (the
// shallowest place when there are several).
std::optional<std::string> home_of(const std::string& key) {
  std::optional<std::string> best;
  for (const auto& path : property_paths()) {
    const bool match = path == key || (path.size() > key.size() &&
                                       path.compare(path.size() - key.size() - 1, std::string::npos,
                                                    "." + key) == 0);
    if (match && (!best || path.size() < best->size())) best = path;
  }
  return best;
}

std::string unknown_key_message(const std::string& key, const std::vector<std::string>& known) {
  if (auto guess = closest_match(key, known)) return "unknown key; did you mean '" + *guess + "'?";
  if (auto home = home_of(key)) return "unknown key here; did you mean '" + *home + "'?";
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  return "unknown key; expected one of: " + list;
}

void object_problems(const json& value, const json& node, const std::string& pointer,
                     std::vector<Issue>& out) {
  if (!value.is_object()) return;
  if (node.contains("required"))
    for (const auto& key : node["required"])
      if (!value.contains(key.get<std::string>()))
        out.push_back({child_pointer(pointer, key.get<std::string>()), "required key is missing"});
  if (node.value("additionalProperties", true) == false) {
    const auto known = property_names(node);
    for (const auto& [key, child] : value.items())
      if (std::find(known.begin(), known.end(), key) == known.end())
        out.push_back({child_pointer(pointer, key), unknown_key_message(key, known)});
  }
}

// --- oneOf over groups of required keys: "give lambda and mu, or youngs_modulus and ..." ---

using Group = std::vector<std::string>;

std::vector<Group> required_groups(const json& node) {
  std::vector<Group> groups;
  if (!node.contains("oneOf")) return groups;
  for (const auto& branch : node["oneOf"]) {
    if (!branch.contains("required")) return {};  // not a choice between key groups
    groups.push_back(branch["required"].get<Group>());
  }
  return groups;
}

std::string join(const std::vector<std::string>& words, const std::string& sep,
                 const std::string& last_sep) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i)
    out += (i == 0 ? "" : i + 1 == words.size() ? last_sep : sep) + words[i];
  return out;
}

std::string alternatives(const std::vector<Group>& groups) {
  std::vector<std::string> texts;
  bool singles = true;
  for (const auto& g : groups) {
    texts.push_back(join(g, ", ", " and "));
    singles = singles && g.size() == 1;
  }
  return singles ? "exactly one of " + join(texts, ", ", " or ")
                 : "either " + join(texts, ", or ", ", or ");
}

Problem group_problem(const json& value, const json& node) {
  const auto groups = required_groups(node);
  if (groups.empty() || !value.is_object()) return std::nullopt;
  std::vector<std::string> found;
  std::vector<std::size_t> touched;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    bool any = false;
    for (const auto& key : groups[i])
      if (value.contains(key)) {
        any = true;
        if (std::find(found.begin(), found.end(), key) == found.end()) found.push_back(key);
      }
    if (any) touched.push_back(i);
  }
  if (touched.empty()) return "give " + alternatives(groups);
  if (touched.size() > 1)
    return "give " + alternatives(groups) + (groups.size() == 2 ? ", not both" : ", not several") +
           " (found " + join(found, ", ", ", ") + ")";
  const Group& group = groups[touched.front()];
  std::vector<std::string> missing;
  for (const auto& key : group)
    if (!value.contains(key)) missing.push_back(key);
  if (missing.empty()) return std::nullopt;
  return join(missing, ", ", " and ") + (missing.size() == 1 ? " is" : " are") + " missing (" +
         join(group, ", ", " and ") + " go together)";
}

std::string with_hint(std::string message, const json& node, const char* keyword) {
  if (node.contains("x-hints") && node["x-hints"].contains(keyword))
    message += "; " + node["x-hints"][keyword].get<std::string>();
  return message;
}

}  // namespace

std::string describe_value(const json& value) {
  if (value.is_string()) {
    auto text = value.get<std::string>();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return "'" + text + "'";
  }
  if (value.is_array()) return "a list of " + items_text(value.size());
  if (value.is_object()) return "a mapping";
  if (value.is_null()) return "nothing (null)";
  return value.dump();
}

std::vector<Issue> describe_violations(const json& value, const json& referring_node,
                                       const std::string& pointer) {
  const json& node = resolve_ref(referring_node);
  // A value of the wrong type makes every other keyword meaningless.
  if (auto p = type_problem(value, node)) return {{pointer, with_hint(*p, node, "type")}};
  std::vector<Issue> issues;
  const std::pair<const char*, Problem> local[] = {
      {"enum", enum_problem(value, node)},   {"bounds", bound_problem(value, node)},
      {"size", size_problem(value, node)},   {"string", string_problem(value, node)},
      {"oneOf", group_problem(value, node)},
  };
  for (const auto& [keyword, problem] : local)
    if (problem) issues.push_back({pointer, with_hint(*problem, node, keyword)});
  object_problems(value, node, pointer, issues);
  return issues;
}

}  // namespace mrsim::scenario
