#pragma once
// log.h5 against log.h5: every dataset and every attribute, by name. The `scenario` root
// attribute is compared as a scenario (scenario_diff.hpp), and the items that differ between
// two runs of the same build by design are left out (kIgnoredLogItems).
#include <array>
#include <filesystem>
#include <string_view>

#include "compare/compare_report.hpp"
#include "compare/tolerance.hpp"

namespace mrsim {

/// The wall-clock time per frame (and per task), when the run started, and which build ran it.
inline constexpr std::array<std::string_view, 5> kIgnoredLogItems = {
    "/frames/wall_time", "/frames/wall_time_parts", "/@start_time", "/@mrsim_version",
    "/@git_revision"};

/// Adds to `report` (Section::Log). Throws InputError naming the file when either log cannot
/// be read.
void diff_logs(const std::filesystem::path& a, const std::filesystem::path& b,
               const Tolerance& tolerance, CompareReport& report);

}  // namespace mrsim
