#pragma once
// Deep comparison of two JSON documents (the resolved scenarios, the summaries): numbers
// within the tolerance, except that two integers compare exactly (counters and step counts,
// as in log.h5); strings, booleans, nulls and the structure exactly. Differences are named
// by key path ("material.lambda", "object.levels.0.mesh": the form `--set` takes).
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "compare/tolerance.hpp"

namespace mrsim {

struct JsonDifference {
  std::string path;  // key path; "(document)" for the root
  std::string a;     // the value in A as text, "(missing)" when the key is absent
  std::string b;
};

struct JsonDiff {
  std::vector<JsonDifference> differences;
  std::size_t compared = 0;          // leaf values (and keys present on one side) compared
  std::vector<std::string> ignored;  // key paths left out, as met
};

/// True for an object key to leave out; it receives the key path and the key itself.
using IgnoreKey = std::function<bool(const std::string& path, const std::string& key)>;

JsonDiff diff_json(const nlohmann::json& a, const nlohmann::json& b, const Tolerance& tolerance,
                   const IgnoreKey& ignore = {});

/// A value as the report shows it: numbers in their shortest exact form, strings quoted,
/// containers as compact JSON cut to about 80 characters.
std::string json_value_text(const nlohmann::json& value);

}  // namespace mrsim
