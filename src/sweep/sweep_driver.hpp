#pragma once
// `mrsim sweep`: check every case up front, lay out DIR, run what the resume rule asks for
// and rebuild DIR/results.csv. The CLI (src/cli/sweep_command.cpp) only parses arguments.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mrsim::sweep {

struct SweepOptions {
  std::filesystem::path sweep_file;
  std::string output;              // -o; "" = the file's `output`
  int jobs = 1;                    // -j: cases at a time
  int threads = 0;                 // --threads per case; 0 = max(1, cores / jobs)
  bool retry_failed = false;       // re-run cases whose status.json has a non-zero exit code
  bool quiet = false;              // no progress on stderr
  bool collect_only = false;       // --collect: only rebuild results.csv
  std::optional<int> only_case;    // --case K: run case K alone (a Slurm array task)
  std::string emit;                // --emit slurm: write the job scripts, run nothing
  std::vector<std::string> sbatch_options;  // --sbatch-option: extra #SBATCH lines
  std::filesystem::path executable = "/proc/self/exe";  // the binary the cases run with
};

/// Returns 0 when every case (or case K) is done, 1 when some failed; throws InputError
/// (exit 2) before writing anything for a bad sweep file or a case whose scenario does not
/// load. With --collect, returns 0 once results.csv is written; with --emit slurm, once the
/// scripts are written (every case checked first, as for a local run).
int run_sweep(const SweepOptions& options);

}  // namespace mrsim::sweep
