#pragma once
// DIR/results.csv, rebuilt from every case folder (never appended to, so a partial or
// repeated run cannot leave stale rows). Columns, read by scripts/plot_sweep.py:
// case,status,exit_code,message,param:<key>...,peak_tool_force,max_displacement,
// final_active_L0..L{n-1},wall_time,force_evaluations,steps,splits,merges
#include <filesystem>
#include <string>
#include <vector>

#include "sweep/sweep_cases.hpp"

namespace mrsim::sweep {

/// The whole CSV text for `cases` of the sweep in `sweep_dir`. Pending cases (no
/// status.json) have status `pending` and empty figures; figures come from each
/// summary.json (force_evaluations summed over levels; n = the most levels of any case).
std::string results_csv(const std::filesystem::path& sweep_dir,
                        const std::vector<std::string>& keys,
                        const std::vector<SweepCase>& cases);

/// cases.csv: `case` then one column per parameter (written before anything runs).
std::string cases_csv(const std::vector<std::string>& keys, const std::vector<SweepCase>& cases);

/// A CSV field, quoted when it holds a comma, a quote or a line break (RFC 4180).
std::string csv_field(const std::string& text);

}  // namespace mrsim::sweep
