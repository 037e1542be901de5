#include "cli/sweep_command.hpp"

#include <memory>

#include "sweep/sweep_driver.hpp"

namespace mrsim {
namespace {

const char* const kFooter =
    "Runs each case as `mrsim run BASE --set ... -o DIR/case_NNNN` in a child process, with\n"
    "OMP_WAIT_POLICY=PASSIVE unless set. Re-running skips finished cases (and failed ones\n"
    "unless --retry-failed); a case folder without status.json is cleared and re-run.\n"
    "DIR/results.csv is rebuilt at the end. Exit codes: 0 all done, 1 some failed, 2 bad input.\n"
    "See docs/sweeps.md.";

struct SweepArgs {
  sweep::SweepOptions options;
  int only_case = -1;
};

}  // namespace

SweepCommand add_sweep_command(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  auto& o = args->options;
  CLI::App* cmd = app.add_subcommand("sweep", "Run the cases of a parameter sweep");
  cmd->footer(kFooter);
  cmd->add_option("sweep", o.sweep_file, "Sweep file (YAML)")->required();
  cmd->add_option("-o,--output", o.output, "Sweep folder (overrides the file's `output`)");
  cmd->add_option("-j,--jobs", o.jobs, "Cases run at a time (default 1)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--threads", o.threads, "OpenMP threads per case (default: cores / jobs)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--retry-failed", o.retry_failed, "Re-run the cases that failed before");
  cmd->add_flag("-q,--quiet", o.quiet, "No progress on stderr");
  auto* collect =
      cmd->add_flag("--collect", o.collect_only, "Only rebuild DIR/results.csv from the cases");
  auto* only = cmd->add_option("--case", args->only_case,
                               "Run case K only (e.g. a Slurm array task)")
                   ->check(CLI::NonNegativeNumber)
                   ->excludes(collect);
  cmd->add_option("--emit", o.emit,
                  "Write DIR/sweep.sbatch (a Slurm job array, one task per case), "
                  "DIR/collect.sbatch and DIR/submit.sh instead of running (docs/slurm.md)")
      ->check(CLI::IsMember({"slurm"}))
      ->excludes(collect)
      ->excludes(only);
  cmd->add_option("--sbatch-option", o.sbatch_options,
                  "An extra #SBATCH line for the emitted scripts, e.g. --sbatch-option "
                  "--partition=compute (repeatable)")
      ->allow_extra_args(false);
  return {cmd, [args] {
            if (args->only_case >= 0) args->options.only_case = args->only_case;
            return sweep::run_sweep(args->options);
          }};
}

}  // namespace mrsim
