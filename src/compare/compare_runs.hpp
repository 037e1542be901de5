#pragma once
// `mrsim compare RUN_A RUN_B`: two output folders of `mrsim run`, file by file (docs/output.md
// "Comparing runs"): scenario.yaml, log.h5, the VTK series, summary.json.
#include <filesystem>

#include "compare/compare_report.hpp"
#include "compare/tolerance.hpp"

namespace mrsim {

/// Every difference beyond `tolerance`, in a report ready to print. Throws InputError naming
/// the file when an input cannot be read: a missing folder, a missing or corrupt log.h5 or
/// scenario.yaml, a listed frame or piece that is missing or unreadable, a malformed
/// frames.pvd or summary.json.
CompareReport compare_runs(const std::filesystem::path& run_a, const std::filesystem::path& run_b,
                           const Tolerance& tolerance);

}  // namespace mrsim
