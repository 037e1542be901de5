// The emitted Slurm scripts (docs/slurm.md): one array task per case running `--case K`, a
// collect job, absolute quoted paths, site lines, and OpenMP kept to the task's CPUs.
#include <gtest/gtest.h>

#include "sweep/slurm_scripts.hpp"

using namespace mrsim::sweep;

namespace {

SlurmJob job() {
  SlurmJob j;
  j.executable = "/opt/mrsim/bin/mrsim";
  j.sweep_file = "/home/me/it's.yaml";
  j.dir = "/shared/me/psi";
  j.name = "psi";
  j.cases = 12;
  j.cpus_per_task = 4;
  j.sbatch_options = {"--partition=compute", "--time=01:00:00"};
  return j;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST(SlurmScripts, ArrayHasOneTaskPerCaseEachRunningItsCase) {
  const std::string s = slurm_array_script(job());
  EXPECT_EQ(s.rfind("#!/bin/bash\n", 0), 0u);
  EXPECT_TRUE(has(s, "#SBATCH --array=0-11\n"));
  EXPECT_TRUE(has(s, "#SBATCH --cpus-per-task=4\n"));
  EXPECT_TRUE(has(s, "#SBATCH --output=/shared/me/psi/slurm-%A_%a.out\n"));
  EXPECT_TRUE(has(s, "#SBATCH --partition=compute\n#SBATCH --time=01:00:00\n"));
  EXPECT_TRUE(has(s, "export OMP_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}\n"));
  EXPECT_TRUE(has(s, "OMP_WAIT_POLICY"));
  EXPECT_TRUE(has(s, "exec '/opt/mrsim/bin/mrsim' sweep '/home/me/it'\\''s.yaml' -o "
                     "'/shared/me/psi' --quiet --threads \"$OMP_NUM_THREADS\" --case "
                     "\"$SLURM_ARRAY_TASK_ID\"\n"));
  // #SBATCH lines count only before the first command.
  EXPECT_LT(s.rfind("#SBATCH"), s.find("export"));
}

TEST(SlurmScripts, CollectRebuildsTheTableOnOneCpu) {
  const std::string s = slurm_collect_script(job());
  EXPECT_FALSE(has(s, "--array"));
  EXPECT_TRUE(has(s, "#SBATCH --cpus-per-task=1\n"));
  EXPECT_TRUE(has(s, "#SBATCH --partition=compute\n"));
  EXPECT_TRUE(has(s, "-o '/shared/me/psi' --collect\n"));
}

TEST(SlurmScripts, SubmitChainsCollectAfterAnyTaskEnd) {
  const std::string s = slurm_submit_script(job());
  EXPECT_TRUE(has(s, "sbatch --parsable '/shared/me/psi/sweep.sbatch'"));
  EXPECT_TRUE(has(s, "--dependency=afterany:\"$array\" '/shared/me/psi/collect.sbatch'"));
}
