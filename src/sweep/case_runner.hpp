#pragma once
// Runs cases as child processes of this binary (`mrsim run ... -o DIR/case_NNNN`), N at a
// time. A child that fails or is killed is recorded in its status.json; the others go on.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sweep/case_folder.hpp"

namespace mrsim::sweep {

struct CaseJob {
  int index = 0;
  std::filesystem::path folder;        // DIR/case_NNNN, prepared (params.json written)
  std::vector<std::string> overrides;  // every --set of the case
  bool resume = false;                 // go on from the folder's checkpoint (can_resume)
};

struct RunnerOptions {
  std::filesystem::path executable = "/proc/self/exe";
  std::filesystem::path base;  // the base scenario
  int jobs = 1;                // cases at a time
  int threads = 1;             // --threads of each child
};

/// The child's argv (without argv[0] substitution): `EXE run BASE --set ... -o FOLDER --quiet
/// --threads T`.
std::vector<std::string> child_arguments(const RunnerOptions& options, const CaseJob& job);

/// This process's environment plus OMP_WAIT_POLICY=PASSIVE unless the user set it: OpenMP
/// threads spin while idle by default, and several spinning processes on one machine starve
/// each other (30x slowdowns measured in this project).
std::vector<std::string> child_environment();

/// The failure text of a child from its stderr: the last "error: ..." line and what follows
/// it (without the prefix), else the last non-empty line.
std::string failure_message(const std::string& stderr_text);

/// Runs every job, at most `options.jobs` at once, writing each status.json when its child
/// ends. `on_start` / `on_finish` report progress (called from this thread).
void run_cases(const std::vector<CaseJob>& jobs, const RunnerOptions& options,
               const std::function<void(const CaseJob&)>& on_start,
               const std::function<void(const CaseJob&, const CaseStatus&)>& on_finish);

/// Default threads per child: the cores shared out between the `jobs` children.
int default_threads(int jobs);

}  // namespace mrsim::sweep
