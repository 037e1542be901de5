#pragma once
// The resolved scenarios of two runs (scenario.yaml, and the `scenario` attribute of log.h5),
// compared as data rather than text: parsed, `output.dir` left out (where a run was written
// says nothing about what it computed), then compared key by key (json_diff.hpp).
#include <string>
#include <string_view>

#include "compare/json_diff.hpp"

namespace mrsim {

struct YamlText {
  std::string_view text;
  std::string origin;  // named in parse errors: "run_a/scenario.yaml"
};

/// Throws InputError (naming the origin, line and column) when either text is not valid YAML.
JsonDiff diff_scenarios(const YamlText& a, const YamlText& b, const Tolerance& tolerance);

}  // namespace mrsim
