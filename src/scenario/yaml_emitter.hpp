#pragma once
// JSON -> block-style YAML for the resolved scenario. Written by hand rather than with
// YAML::Emitter to control exactly how numbers and strings come out: they must read back
// as the same values both here (YAML 1.2 core schema) and in PyYAML (YAML 1.1), which users
// load the resolved scenario with.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace mrsim::scenario {

/// Shortest text that reads back as exactly `value` and as a float in YAML 1.1 and 1.2:
/// always a '.', exponents signed ("1.0e+5", "0.04", "-9.81", "1000.0").
/// Throws std::invalid_argument for a non-finite value (YAML readers differ on them).
std::string yaml_float(double value);

/// A plain scalar when that reads back as the same string everywhere, else double-quoted.
std::string yaml_string(const std::string& text);

/// Block mappings and lists; lists of scalars in flow style ("[0, 0, -9.81]"). Keys of a
/// mapping come in the order of `key_order`, unlisted keys after them alphabetically.
std::string to_block_yaml(const nlohmann::json& document,
                          const std::vector<std::string>& key_order = {});

}  // namespace mrsim::scenario
