#include "compare/summary_diff.hpp"

namespace mrsim {

bool is_ignored_summary_key(const std::string& key) {
  // What describes the machine and the build, not the run's results.
  return key.find("wall") != std::string::npos || key == "real_time_factor" ||
         key == "mrsim_version" || key == "git_revision" || key == "force_kernel";
}

JsonDiff diff_summaries(const nlohmann::json& a, const nlohmann::json& b,
                        const Tolerance& tolerance) {
  return diff_json(a, b, tolerance, [](const std::string&, const std::string& key) {
    return is_ignored_summary_key(key);
  });
}

}  // namespace mrsim
