#include "cli/compare_command.hpp"

#include <cmath>
#include <iostream>
#include <memory>
#include <new>

#include "compare/compare_runs.hpp"
#include "core/error.hpp"

namespace mrsim {
namespace {

struct CompareArgs {
  std::string run_a;
  std::string run_b;
  Tolerance tolerance;
};

const char* const kFooter =
    "Compares scenario.yaml (without output.dir), every dataset and attribute of log.h5, every\n"
    "frame of frames.pvd (points, cells, point/cell/field arrays of each block) and summary.json.\n"
    "Floats are equal when |a-b| <= atol + rtol*max(|a|,|b|) (NaN = NaN). Integers (work "
    "counters,\n"
    "active/ghost counts, status, events, connectivity) are compared exactly whatever the\n"
    "tolerances. Ignored: log.h5 /frames/wall_time and the root attributes start_time,\n"
    "mrsim_version, git_revision; summary.json wall_time, mrsim_version, git_revision,\n"
    "force_kernel.\n"
    "Exit codes: 0 equal, 1 different (report on stdout), 2 unreadable input.";

// Both tolerances: finite and >= 0 (CLI::NonNegativeNumber lets "nan" through).
const CLI::Validator kNonNegative(
    [](std::string& text) {
      double value = 0;
      if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || value < 0) {
        return "must be a finite number >= 0, got " + text;
      }
      return std::string();
    },
    "NONNEGATIVE");

int run_compare(const CompareArgs& a) {
  CompareReport report = [&] {
    // Exit code 1 means "differ": a failure of any kind to read the inputs must be 2.
    try {
      return compare_runs(a.run_a, a.run_b, a.tolerance);
    } catch (const InputError&) {
      throw;
    } catch (const std::bad_alloc&) {
      throw InputError("out of memory while reading the runs");
    } catch (const std::exception& e) {
      throw InputError(e.what());
    }
  }();
  report.print(std::cout, a.tolerance);
  return report.identical() ? kExitOk : kExitDiffer;
}

}  // namespace

CompareCommand add_compare_command(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "Compare two output folders of `mrsim run` (golden-file regression)");
  cmd->footer(kFooter);
  cmd->add_option("RUN_A", args->run_a, "Output folder A (e.g. the golden run)")->required();
  cmd->add_option("RUN_B", args->run_b, "Output folder B")->required();
  cmd->add_option("--rtol", args->tolerance.rtol,
                  "Relative tolerance on floats (default 0: identical values)")
      ->check(kNonNegative);
  cmd->add_option("--atol", args->tolerance.atol, "Absolute tolerance on floats (default 0)")
      ->check(kNonNegative);
  return {cmd, [args] { return run_compare(*args); }};
}

}  // namespace mrsim
