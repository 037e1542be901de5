#pragma once
// YAML text -> JSON, built from yaml-cpp's event stream rather than YAML::Node so that we keep
// the position of every key and value, see duplicate keys (which YAML::Node silently merges)
// and never walk a recursive alias (which makes YAML::Node recurse forever).
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "scenario/source_map.hpp"

namespace mrsim::scenario {

struct YamlDocument {
  nlohmann::json value;
  SourceMap positions;
};

struct YamlOptions {
  std::string origin;     // named in every message: the file, or "--set key=value"
  bool positions = true;  // false: a one-line override; line:column and key paths are noise
  int rank = 0;           // Location::rank given to every recorded position
};

/// Parses exactly one YAML document. Throws InputError for syntax errors, duplicate keys,
/// non-string keys, recursive aliases, excessive nesting or size, non-finite numbers,
/// an empty document or several documents.
YamlDocument yaml_to_json(std::string_view text, const YamlOptions& options);

}  // namespace mrsim::scenario
