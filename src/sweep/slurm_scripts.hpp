#pragma once
// `mrsim sweep --emit slurm`: a job array with one task per case (each runs `--case K`, the
// local resume rule included) and a collect job for after it (docs/slurm.md).
#include <filesystem>
#include <string>
#include <vector>

namespace mrsim::sweep {

struct SlurmJob {
  std::filesystem::path executable;  // absolute: tasks run from any folder
  std::filesystem::path sweep_file;  // absolute
  std::filesystem::path dir;         // absolute, on a filesystem the nodes share
  std::string name;                  // job name suffix, e.g. the sweep file's stem
  int cases = 0;
  int cpus_per_task = 1;
  std::vector<std::string> sbatch_options;  // extra `#SBATCH` lines, e.g. "--partition=x"
};

/// The array script (DIR/sweep.sbatch).
std::string slurm_array_script(const SlurmJob& job);

/// The collect script (DIR/collect.sbatch), to submit with --dependency=afterany:ARRAY_ID.
std::string slurm_collect_script(const SlurmJob& job);

/// DIR/submit.sh: submits both with the dependency.
std::string slurm_submit_script(const SlurmJob& job);

}  // namespace mrsim::sweep
