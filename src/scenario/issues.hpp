#pragma once
// A problem found in a scenario, addressed by JSON pointer; turned into the user-facing
// InputError text "file:line:col: key.path: message" (one line per problem).
#include <string>
#include <vector>

#include "scenario/source_map.hpp"

namespace mrsim::scenario {

struct Issue {
  std::string pointer;  // where the problem is ("" = the whole document)
  std::string message;  // what is wrong, e.g. "must be >= 0 (got -5)"
};

/// "file:12:3: material.lambda: must be >= 0 (got -5)".
std::string format_issue(const SourceMap& positions, const Issue& issue);

/// Throws one InputError listing the issues in source order (no-op when `issues` is empty).
void throw_if_any(const SourceMap& positions, std::vector<Issue> issues);

}  // namespace mrsim::scenario
