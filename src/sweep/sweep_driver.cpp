#include "sweep/sweep_driver.hpp"


#include "core/error.hpp"
#include "core/text_file.hpp"
#include "core/log.hpp"
#include "scenario/scenario.hpp"
#include "sweep/case_runner.hpp"
#include "sweep/results_table.hpp"
#include "sweep/slurm_scripts.hpp"
#include "sweep/sweep_progress.hpp"
#include "sweep/sweep_spec.hpp"

namespace mrsim::sweep {

namespace {

namespace fs = std::filesystem;

struct Plan {
  SweepSpec spec;
  fs::path dir;
  std::vector<SweepCase> cases;     // all of them: results.csv lists every case
  std::vector<SweepCase> selected;  // those this invocation is about (all, or case K)
};

Plan make_plan(const SweepOptions& options) {
  Plan plan;
  plan.spec = load_sweep(options.sweep_file);
  const std::string dir = options.output.empty() ? plan.spec.output : options.output;
  if (dir.empty())
    throw InputError(options.sweep_file.string() + ": no output folder: give -o DIR or `output:`");
  plan.dir = dir;
  plan.cases = expand_cases(plan.spec);
  plan.selected = plan.cases;
  if (options.only_case) {
    const int k = *options.only_case;
    if (k < 0 || k >= static_cast<int>(plan.cases.size()))
      throw InputError("--case " + std::to_string(k) + ": the sweep has cases 0 to " +
                       std::to_string(plan.cases.size() - 1));
    plan.selected = {plan.cases[static_cast<std::size_t>(k)]};
  }
  return plan;
}

std::string describe(const SweepCase& c) {
  std::string text;
  for (const auto& [key, value] : c.params)
    text += (text.empty() ? "" : ", ") + key + "=" + yaml_value(value);
  return text;
}

// Every case must load before anything runs: an unknown key or a bad value would otherwise
// surface hours later, in one case of many.
// Loading is silenced: the same warning N times would bury the one error that matters, and
// each case's own warnings are in its stderr.txt.
void check_cases(const Plan& plan) {
  const bool was_quiet = is_quiet();
  set_quiet(true);
  struct Restore {
    bool quiet;
    ~Restore() { set_quiet(quiet); }
  } restore{was_quiet};
  for (const auto& c : plan.selected) {
    try {
      (void)load_scenario(plan.spec.base, case_overrides(plan.spec, c));
    } catch (const InputError& e) {
      throw InputError(case_name(c.index) + " (" + describe(c) + "): " + e.what());
    }
  }
}

// Cases are found again by index, so a folder made by another sweep file must not be mixed in.
void lay_out(const Plan& plan) {
  const fs::path copy = plan.dir / "sweep.yaml";
  if (fs::exists(copy) && read_text_if_any(copy) != plan.spec.text)
    throw InputError(plan.dir.string() + " holds another sweep (its sweep.yaml differs from " +
                     plan.spec.file.string() + "): choose another -o or delete it");
  std::error_code error;
  fs::create_directories(plan.dir, error);
  if (error) throw RunError("cannot create " + plan.dir.string() + ": " + error.message());
  write_file_atomically(copy, plan.spec.text);
  write_file_atomically(plan.dir / "cases.csv",
                        cases_csv(parameter_keys(plan.spec), plan.cases));
}

std::vector<CaseJob> jobs_to_run(const Plan& plan, bool retry_failed) {
  std::vector<CaseJob> jobs;
  for (const auto& c : plan.selected) {
    const fs::path folder = case_folder(plan.dir, c.index);
    if (!needs_run(case_state(folder), retry_failed)) continue;
    // A run stopped by a kill, a time limit or a preemption goes on from its checkpoint.
    const bool resume = can_resume(folder);
    if (resume)
      reopen_case_folder(folder);
    else
      prepare_case_folder(folder, c);
    jobs.push_back({c.index, folder, case_overrides(plan.spec, c), resume});
  }
  return jobs;
}

SweepProgress make_progress(const Plan& plan, const SweepOptions& options) {
  int done = 0, failed = 0;
  for (const auto& c : plan.selected) {
    const CaseState state = case_state(case_folder(plan.dir, c.index));
    done += state == CaseState::done || state == CaseState::failed;
    failed += state == CaseState::failed;
  }
  // Cases about to run were cleared already: those counted here are the skipped ones.
  return SweepProgress(static_cast<int>(plan.selected.size()), done, failed, options.jobs,
                       !options.quiet);
}

void write_results(const Plan& plan) {
  write_file_atomically(plan.dir / "results.csv",
                        results_csv(plan.dir, parameter_keys(plan.spec), plan.cases));
}

int exit_code(const Plan& plan) {
  for (const auto& c : plan.selected)
    if (case_state(case_folder(plan.dir, c.index)) != CaseState::done) return kExitRunFailure;
  return kExitOk;
}

int emit_slurm(const Plan& plan, const SweepOptions& options) {
  if (options.emit != "slurm")
    throw InputError("--emit " + options.emit + ": the only scheduler is slurm");
  SlurmJob job;
  job.executable = fs::canonical(options.executable);
  job.sweep_file = fs::absolute(options.sweep_file).lexically_normal();
  job.dir = fs::absolute(plan.dir).lexically_normal();
  job.name = options.sweep_file.stem().string();
  job.cases = static_cast<int>(plan.cases.size());
  job.cpus_per_task = options.threads > 0 ? options.threads : 1;
  job.sbatch_options = options.sbatch_options;
  write_file_atomically(job.dir / "sweep.sbatch", slurm_array_script(job));
  write_file_atomically(job.dir / "collect.sbatch", slurm_collect_script(job));
  write_file_atomically(job.dir / "submit.sh", slurm_submit_script(job));
  fs::permissions(job.dir / "submit.sh", fs::perms::owner_exec | fs::perms::group_exec,
                  fs::perm_options::add);
  info("mrsim sweep: " + std::to_string(job.cases) + " cases; submit with " +
       (job.dir / "submit.sh").string() + " (sbatch sweep.sbatch, then collect.sbatch with " +
       "--dependency=afterany); docs/slurm.md");
  return kExitOk;
}

}  // namespace

int run_sweep(const SweepOptions& options) {
  const Plan plan = make_plan(options);
  if (options.collect_only) {
    if (!fs::is_directory(plan.dir))
      throw InputError("--collect: no sweep folder " + plan.dir.string());
    write_results(plan);
    return kExitOk;
  }
  check_cases(plan);
  lay_out(plan);
  if (!options.emit.empty()) return emit_slurm(plan, options);
  const std::vector<CaseJob> jobs = jobs_to_run(plan, options.retry_failed);
  SweepProgress progress = make_progress(plan, options);
  RunnerOptions runner;
  runner.executable = options.executable;
  runner.base = plan.spec.base;
  runner.jobs = options.jobs;
  runner.threads = options.threads > 0 ? options.threads : default_threads(options.jobs);
  run_cases(
      jobs, runner, [&](const CaseJob&) { progress.started(); },
      [&](const CaseJob&, const CaseStatus& s) { progress.finished(s.exit_code == 0); });
  progress.close();
  // A Slurm array task runs one case; the final `--collect` builds the table once.
  if (!options.only_case) write_results(plan);
  return exit_code(plan);
}

}  // namespace mrsim::sweep
