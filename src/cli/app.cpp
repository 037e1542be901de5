#include "cli/app.hpp"

#include <omp.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <new>

#include "cli/compare_command.hpp"
#include "cli/guarded_run.hpp"
#include "cli/mesh_command.hpp"
#include "cli/mesher_handoff.hpp"
#include "cli/progress_reporter.hpp"
#include "cli/sweep_command.hpp"
#include "core/error.hpp"
#include "core/interruption.hpp"
#include "core/log.hpp"
#include "mrsim/version.hpp"
#include "physics/green_nodal_forces.hpp"
#include "simulation/run.hpp"

namespace mrsim {

namespace {

struct CommonArgs {
  std::string scenario;
  std::vector<std::string> overrides;
  std::string output;
  std::string resume;  // run --resume OUTDIR
  int threads = 0;
  bool quiet = false;
};

CLI::Option* add_scenario_args(CLI::App* cmd, CommonArgs& a, bool required = true) {
  CLI::Option* scenario = cmd->add_option("scenario", a.scenario, "Scenario file (YAML)");
  if (required) scenario->required();
  cmd->add_option("--set", a.overrides,
                  "Override a scenario key, e.g. --set material.lambda=5.0e+4 (repeatable; "
                  "validated like the file)");
  cmd->add_flag("-q,--quiet", a.quiet, "No progress and no warnings on stderr");
  return scenario;
}

Scenario load(const CommonArgs& a) {
  std::vector<std::string> overrides = a.overrides;
  if (!a.output.empty()) overrides.push_back("output.dir=" + a.output);
  return load_scenario(a.scenario, overrides);
}

// Exit code of a run that ended without an error.
int finished(const RunSummary& s) {
  if (s.interrupted_by == 0) return kExitOk;
  std::cerr << "mrsim: interrupted; every frame written so far is complete, and checkpoint.h5 "
               "lets mrsim run --resume go on (summary.json: status \"interrupted\")\n";
  return 128 + s.interrupted_by;
}

// A run with progress on stderr and clean interruption: `run` gets the options, the summary
// line says what ran (`what`) and where its outputs are.
// " (2.3x real time)": simulated seconds per wall second, the figure a real-time user looks for.
std::string real_time(const RunSummary& s) {
  if (s.wall_time <= 0 || s.simulated_time <= 0) return "";
  char buf[48];
  std::snprintf(buf, sizeof buf, " (%.3gx real time)", real_time_factor(s));
  return buf;
}

template <class Run>
int run_reporting(const CommonArgs& a, const std::string& what, const std::string& dir, Run run) {
  ProgressReporter progress(!a.quiet);
  RunOptions options;
  options.progress = [&](const RunProgress& p) { progress(p); };
  watch_interruptions();
  try {
    const RunSummary s = run(options);
    progress.finish();
    info("mrsim: " + what + std::to_string(s.frames) + " frames, " + std::to_string(s.steps) +
         " steps in " + std::to_string(s.wall_time) + " s" + real_time(s) + "; outputs in " + dir);
    return finished(s);
  } catch (...) {
    progress.finish();
    throw;
  }
}

int command_run(const CommonArgs& a) {
  set_quiet(a.quiet);
  if (a.threads > 0) omp_set_num_threads(a.threads);
  const Scenario sc = load(a);
  return run_reporting(a, "", sc.output.dir.string(),
                       [&](const RunOptions& o) { return run_scenario(sc, o); });
}

// mrsim run --resume OUTDIR: the run goes on from its checkpoint (docs/output.md).
int command_resume(const CommonArgs& a) {
  set_quiet(a.quiet);
  if (a.threads > 0) omp_set_num_threads(a.threads);
  if (!a.scenario.empty() || !a.overrides.empty() || !a.output.empty())
    throw InputError("--resume goes on with the run in its folder, with the scenario it started "
                     "with: give no scenario, --set or -o with it");
  return run_reporting(a, "resumed, whole run: ", a.resume,
                       [&](const RunOptions& o) { return resume_run(a.resume, o); });
}

int command_check(const CommonArgs& a) {
  set_quiet(a.quiet);
  const Scenario sc = check_scenario_inputs(load(a));
  std::cout << resolved_yaml(sc);
  return kExitOk;
}

// MRSIM_KERNEL picks the force kernel's build (physics/green_nodal_forces.hpp); a build this
// processor does not run is an input error, said before anything else runs.
bool apply_kernel_choice() {
  const char* name = std::getenv("MRSIM_KERNEL");
  if (name == nullptr || *name == '\0') return true;
  try {
    choose_green_kernel(name);
    return true;
  } catch (const std::invalid_argument& e) {
    std::cerr << "mrsim: MRSIM_KERNEL: " << e.what() << "\n";
    return false;
  }
}

}  // namespace

int run_cli(int argc, char** argv) {
  if (argc >= 2 && std::string_view(argv[1]) == "mesh") return hand_over_to_mesher(argc, argv, 2);
  if (!apply_kernel_choice()) return kExitBadInput;
  CLI::App app{"mrsim: hierarchical multiresolution soft-body simulator (Debunne's model)"};
  app.set_version_flag("--version", std::string("mrsim ") + kVersion + " (" + kGitRevision + ")\n" +
                                        "Green-Lagrange force kernel: " + green_kernel_name() +
                                        " (this processor runs " + green_kernel_build_list() +
                                        "; MRSIM_KERNEL picks one; all give the same results)");
  app.require_subcommand(1);
  CommonArgs run_args, check_args;
  CLI::App* run = app.add_subcommand("run", "Run a scenario and write its outputs");
  CLI::Option* scenario = add_scenario_args(run, run_args, false);
  run->add_option("-o,--output", run_args.output, "Output folder (overrides output.dir)");
  CLI::Option* resume =
      run->add_option("--resume", run_args.resume,
                      "Go on with the interrupted or killed run in this output folder from its "
                      "checkpoint.h5, exactly as if it had never stopped (no scenario then)");
  scenario->excludes(resume);
  run->callback([scenario, resume] {
    if (scenario->count() == 0 && resume->count() == 0)
      throw CLI::RequiredError("scenario (or --resume OUTDIR)");
  });
  run->add_option("--threads", run_args.threads, "OpenMP threads (default: all cores)")
      ->check(CLI::PositiveNumber);
  CLI::App* check = app.add_subcommand(
      "check", "Validate a scenario and its meshes; print the resolved scenario");
  add_scenario_args(check, check_args);
  // Listed for --help; `mrsim mesh ...` never reaches the parser (hand_over_to_mesher above).
  app.add_subcommand("mesh", std::string(kMeshDescription) + " (mrsim mesh --help)");
  const CompareCommand compare = add_compare_command(app);
  const SweepCommand sweep = add_sweep_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  return guarded_run([&] {
    if (*run) return run_args.resume.empty() ? command_run(run_args) : command_resume(run_args);
    if (*compare.command) return compare.run();
    if (*sweep.command) return sweep.run();
    return command_check(check_args);
  });
}

}  // namespace mrsim
