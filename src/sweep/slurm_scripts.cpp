#include "sweep/slurm_scripts.hpp"

#include <sstream>

namespace mrsim::sweep {

namespace {

// Paths go into a shell script: single quotes, with embedded quotes closed and escaped.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

void header(std::ostringstream& s, const SlurmJob& job, const std::string& kind,
            const std::string& output) {
  s << "#!/bin/bash\n"
    << "# Written by `mrsim sweep --emit slurm` (docs/slurm.md); edit freely before submitting.\n"
    << "#SBATCH --job-name=mrsim-" << kind << "-" << job.name << "\n"
    << "#SBATCH --cpus-per-task=" << (kind == "sweep" ? job.cpus_per_task : 1) << "\n"
    << "#SBATCH --output=" << (job.dir / output).string() << "\n";
  if (kind == "sweep") s << "#SBATCH --array=0-" << job.cases - 1 << "\n";
  for (const std::string& line : job.sbatch_options) s << "#SBATCH " << line << "\n";
}

std::string command(const SlurmJob& job) {
  return quoted(job.executable.string()) + " sweep " + quoted(job.sweep_file.string()) +
         " -o " + quoted(job.dir.string());
}

}  // namespace

std::string slurm_array_script(const SlurmJob& job) {
  std::ostringstream s;
  header(s, job, "sweep", "slurm-%A_%a.out");
  // One case per task: OpenMP must keep to the task's CPUs and sleep when idle, or tasks
  // sharing a node starve each other (results do not depend on the thread count).
  s << "export OMP_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}\n"
    << "export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-PASSIVE}\n"
    << "exec " << command(job) << " --quiet --threads \"$OMP_NUM_THREADS\""
    << " --case \"$SLURM_ARRAY_TASK_ID\"\n";
  return s.str();
}

std::string slurm_collect_script(const SlurmJob& job) {
  std::ostringstream s;
  header(s, job, "collect", "collect-%j.out");
  s << "exec " << command(job) << " --collect\n";
  return s.str();
}

std::string slurm_submit_script(const SlurmJob& job) {
  std::ostringstream s;
  // afterany, not afterok: the table must list failed and interrupted cases too.
  s << "#!/bin/bash\n"
    << "# Submits the sweep's job array, then the collect job once every task has ended.\n"
    << "set -euo pipefail\n"
    << "array=$(sbatch --parsable " << quoted((job.dir / "sweep.sbatch").string()) << ")\n"
    << "array=${array%%;*}\n"
    << "collect=$(sbatch --parsable --dependency=afterany:\"$array\" "
    << quoted((job.dir / "collect.sbatch").string()) << ")\n"
    << "echo \"submitted job array $array (" << job.cases << " cases) and collect job "
    << "${collect%%;*}\"\n";
  return s.str();
}

}  // namespace mrsim::sweep
