#pragma once
// Expansion of a sweep into its cases, and the text of each value on the command line.
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "sweep/sweep_spec.hpp"

namespace mrsim::sweep {

struct SweepCase {
  int index = 0;
  std::vector<std::pair<std::string, nlohmann::json>> params;  // key path -> value
};

/// Product combinations in odometer order (last product key fastest), each followed by every
/// zip row (zip rows fastest of all). Case k is always the same for the same file, which is
/// what resume and `--case K` rely on.
std::vector<SweepCase> expand_cases(const SweepSpec& spec);

/// The varied key paths: product keys then zip keys, in file order (the CSV columns).
std::vector<std::string> parameter_keys(const SweepSpec& spec);

/// A value as YAML that reads back as exactly the same value: floats always carry a '.' and
/// a signed exponent when needed ("5.0e+4"), integers stay integers, strings are quoted
/// when plain would change their meaning, lists and mappings in flow style.
std::string yaml_value(const nlohmann::json& value);

/// A value for a CSV cell or a message: shortest round-trip number ("50000", "0.04"),
/// a string as it is, anything else as compact JSON.
std::string plain_value(const nlohmann::json& value);

/// "case_0007".
std::string case_name(int index);

/// Every override of one case: the sweep's `set` then "key=value" per parameter.
std::vector<std::string> case_overrides(const SweepSpec& spec, const SweepCase& c);

}  // namespace mrsim::sweep
