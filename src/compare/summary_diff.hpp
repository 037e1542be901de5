#pragma once
// summary.json against summary.json (json_diff.hpp rules), leaving out what changes between
// two runs of the same computation: wall-clock times and the build that ran it.
#include <nlohmann/json.hpp>
#include <string>

#include "compare/json_diff.hpp"

namespace mrsim {

/// True for `wall_time` (any key whose name contains "wall") and `real_time_factor`, and for
/// `mrsim_version`, `git_revision` and `force_kernel`, as in log.h5.
bool is_ignored_summary_key(const std::string& key);

JsonDiff diff_summaries(const nlohmann::json& a, const nlohmann::json& b,
                        const Tolerance& tolerance);

}  // namespace mrsim
