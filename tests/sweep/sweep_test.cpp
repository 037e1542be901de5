// Unit tests of mrsim sweep (issue 8): expansion, value text, sweep-file errors, the resume
// rule and results.csv. The end-to-end runs are in tests/python/test_sweep.py.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "io/temp_dir.hpp"
#include "scenario/yaml_to_json.hpp"
#include "sweep/case_folder.hpp"
#include "sweep/case_runner.hpp"
#include "sweep/results_table.hpp"
#include "sweep/sweep_cases.hpp"
#include "sweep/sweep_spec.hpp"

namespace fs = std::filesystem;
using namespace mrsim::sweep;
using nlohmann::json;

namespace {

std::string error_of(const std::string& text) {
  try {
    parse_sweep_text(text, "dir/sweep.yaml");
  } catch (const mrsim::InputError& e) {
    return e.what();
  }
  return "";
}

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

const char* const kSweep =
    "base: ../scenarios/beam.yaml\n"
    "output: out/s\n"
    "set: [\"time.duration=0.4\"]\n"
    "product:\n"
    "  material.lambda: [0, 5.0e+4, 5.0e+5]\n"
    "  material.damping.psi: [2, 20]\n"
    "zip:\n"
    "  tool.contact.stiffness: [1.0e+3, 2.0e+3]\n"
    "  time.courant: [0.5, 0.4]\n";

}  // namespace

TEST(SweepSpec, ReadsKeysInFileOrderAndResolvesBase) {
  const SweepSpec spec = parse_sweep_text(kSweep, "dir/sweep.yaml");
  EXPECT_EQ(spec.base, fs::path("dir/../scenarios/beam.yaml"));
  EXPECT_EQ(spec.output, "out/s");
  ASSERT_EQ(spec.set.size(), 1u);
  EXPECT_EQ(parameter_keys(spec),
            (std::vector<std::string>{"material.lambda", "material.damping.psi",
                                      "tool.contact.stiffness", "time.courant"}));
}

TEST(SweepCases, ProductTimesZipInOdometerOrder) {
  const auto cases = expand_cases(parse_sweep_text(kSweep, "s.yaml"));
  ASSERT_EQ(cases.size(), 12u);  // 3 x 2 product combinations x 2 zip rows
  auto value = [&](int c, int p) { return plain_value(cases[c].params[p].second); };
  // Zip rows vary fastest, then the last product key.
  EXPECT_EQ(value(0, 0) + " " + value(0, 1) + " " + value(0, 2) + " " + value(0, 3),
            "0 2 1000 0.5");
  EXPECT_EQ(value(1, 2) + " " + value(1, 3), "2000 0.4");
  EXPECT_EQ(value(2, 1) + " " + value(2, 2), "20 1000");
  EXPECT_EQ(value(4, 0), "50000");
  EXPECT_EQ(value(11, 0) + " " + value(11, 1) + " " + value(11, 3), "500000 20 0.4");
  for (int c = 0; c < 12; ++c) EXPECT_EQ(cases[c].index, c);
}

TEST(SweepCases, ProductAloneAndZipAlone) {
  EXPECT_EQ(expand_cases(parse_sweep_text("base: b.yaml\nproduct: {a: [1, 2], b: [3, 4, 5]}\n",
                                          "s.yaml")).size(), 6u);
  EXPECT_EQ(expand_cases(parse_sweep_text("base: b.yaml\nzip: {a: [1, 2], b: [3, 4]}\n",
                                          "s.yaml")).size(), 2u);
}

TEST(SweepCases, ValuesReadBackExactly) {
  const auto doc = mrsim::scenario::yaml_to_json(
      "v: [5.0e+4, 0.1, 1.0e-7, 3, -2.5, \"yes\", cauchy, [0, 0, -9.81], {a: 1}, true, 1.0e+300]",
      {"t", true, 0});
  for (const json& v : doc.value["v"]) {
    const std::string text = yaml_value(v);
    const auto back = mrsim::scenario::yaml_to_json("x: " + text, {"t", true, 0});
    EXPECT_EQ(back.value["x"], v) << text;
    EXPECT_EQ(back.value["x"].type(), v.type()) << text;
  }
  EXPECT_EQ(yaml_value(json(5.0e+4)), "50000.0");  // a float, not the integer 50000
  EXPECT_EQ(yaml_value(json(1.0e-7)), "1.0e-7");
  EXPECT_EQ(yaml_value(json(2)), "2");
  EXPECT_EQ(yaml_value(json::parse("[0, 0, -9.81]")), "[0, 0, -9.81]");
}

TEST(SweepCases, OverridesAreSetThenParameters) {
  const SweepSpec spec = parse_sweep_text(kSweep, "s.yaml");
  const auto overrides = case_overrides(spec, expand_cases(spec)[5]);
  EXPECT_EQ(overrides, (std::vector<std::string>{
                           "time.duration=0.4", "material.lambda=50000.0",
                           "material.damping.psi=2", "tool.contact.stiffness=2000.0",
                           "time.courant=0.4"}));
  EXPECT_EQ(case_name(7), "case_0007");
}

TEST(SweepSpec, SchemaErrorsNameFileLineAndColumn) {
  const std::string unknown = error_of("base: b.yaml\nproduct: {a: [1]}\nfrobnicate: 1\n");
  EXPECT_NE(unknown.find("dir/sweep.yaml:3:1"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("frobnicate"), std::string::npos) << unknown;
  const std::string not_list = error_of("base: b.yaml\nproduct:\n  material.lambda: 5\n");
  EXPECT_NE(not_list.find("dir/sweep.yaml:3:3"), std::string::npos) << not_list;
  EXPECT_NE(not_list.find("material.lambda"), std::string::npos) << not_list;
  EXPECT_NE(error_of("base: b.yaml\n").find("dir/sweep.yaml"), std::string::npos);
  EXPECT_NE(error_of("product: {a: [1]}\n").find("base"), std::string::npos);
  EXPECT_NE(error_of("base: b.yaml\nproduct: {a: []}\n"), "");
  EXPECT_NE(error_of("base: [\n").find("dir/sweep.yaml"), std::string::npos);  // YAML syntax
}

TEST(SweepSpec, UnequalZipListsAreAnError) {
  const std::string e = error_of("base: b.yaml\nzip:\n  a: [1, 2]\n  b: [1, 2, 3]\n");
  EXPECT_NE(e.find("same length"), std::string::npos) << e;
  EXPECT_NE(e.find("dir/sweep.yaml:4:3"), std::string::npos) << e;
}

TEST(SweepSpec, KeyInProductAndZipIsAnError) {
  const std::string e = error_of("base: b.yaml\nproduct: {a: [1, 2]}\nzip: {a: [1, 2]}\n");
  EXPECT_NE(e.find("both product and zip"), std::string::npos) << e;
}

TEST(CaseFolder, ResumeDecisionFromStatusFiles) {
  const mrsim::test::TempDir tmp;  // removed with the test
  const fs::path& dir = tmp.path();
  EXPECT_EQ(case_state(case_folder(dir, 0)), CaseState::pending);
  fs::create_directories(case_folder(dir, 1));
  EXPECT_EQ(case_state(case_folder(dir, 1)), CaseState::interrupted);
  fs::create_directories(case_folder(dir, 2));
  write_status(case_folder(dir, 2), {0, "", 1.5});
  EXPECT_EQ(case_state(case_folder(dir, 2)), CaseState::done);
  fs::create_directories(case_folder(dir, 3));
  write_status(case_folder(dir, 3), {1, "diverged", 0.5});
  EXPECT_EQ(case_state(case_folder(dir, 3)), CaseState::failed);
  write(case_folder(dir, 4) / "status.json", "{\"exit_co");  // torn: as if absent
  EXPECT_EQ(case_state(case_folder(dir, 4)), CaseState::interrupted);

  EXPECT_TRUE(needs_run(CaseState::pending, false));
  EXPECT_TRUE(needs_run(CaseState::interrupted, false));
  EXPECT_FALSE(needs_run(CaseState::done, false));
  EXPECT_FALSE(needs_run(CaseState::done, true));
  EXPECT_FALSE(needs_run(CaseState::failed, false));
  EXPECT_TRUE(needs_run(CaseState::failed, true));
  const auto status = read_status(case_folder(dir, 3));
  ASSERT_TRUE(status);
  EXPECT_EQ(status->message, "diverged");
  EXPECT_DOUBLE_EQ(status->wall_time, 0.5);
}

// A run stopped cleanly by SIGINT/SIGTERM (a time limit) is interrupted, not failed; with the
// checkpoint its run left, it goes on (mrsim run --resume) instead of starting again.
TEST(CaseFolder, StoppedRunsWithACheckpointGoOn) {
  const mrsim::test::TempDir tmp;  // removed with the test
  const fs::path& dir = tmp.path();
  for (int k = 0; k < 4; ++k) {
    for (const char* f : {"checkpoint.h5", "scenario.yaml", "log.h5"})
      write(case_folder(dir, k) / f, "x");
  }
  write_status(case_folder(dir, 0), {143, "interrupted", 9.0});
  write_status(case_folder(dir, 1), {130, "interrupted", 9.0});
  write_status(case_folder(dir, 2), {1, "diverged", 9.0});
  // case 3: no status.json (the sweep was killed while it ran)
  EXPECT_EQ(case_state(case_folder(dir, 0)), CaseState::interrupted);
  EXPECT_EQ(case_state(case_folder(dir, 1)), CaseState::interrupted);
  EXPECT_TRUE(can_resume(case_folder(dir, 0)));
  EXPECT_TRUE(can_resume(case_folder(dir, 1)));
  EXPECT_FALSE(can_resume(case_folder(dir, 2)));  // failed: cleared and run again if retried
  EXPECT_TRUE(can_resume(case_folder(dir, 3)));
  fs::remove(case_folder(dir, 3) / "checkpoint.h5");
  EXPECT_FALSE(can_resume(case_folder(dir, 3)));  // killed before its first checkpoint
  reopen_case_folder(case_folder(dir, 0));
  EXPECT_FALSE(fs::exists(case_folder(dir, 0) / "status.json"));
  EXPECT_TRUE(fs::exists(case_folder(dir, 0) / "log.h5"));
}

TEST(CaseFolder, PrepareClearsLeftOversAndWritesParams) {
  const mrsim::test::TempDir tmp;  // removed with the test
  const fs::path& dir = tmp.path();
  write(case_folder(dir, 0) / "log.h5", "stale");
  prepare_case_folder(case_folder(dir, 0), {0, {{"material.lambda", json(5.0e+4)}}});
  EXPECT_FALSE(fs::exists(case_folder(dir, 0) / "log.h5"));
  std::ifstream in(case_folder(dir, 0) / "params.json");
  EXPECT_EQ(json::parse(in), json::parse("{\"material.lambda\": 50000.0}"));
}

TEST(ResultsTable, HeaderMatchesThePlotFixture) {
  std::ifstream in(fs::path(MRSIM_SOURCE_DIR) / "tests/data/sweep/results.csv");
  std::string fixture_header;
  std::getline(in, fixture_header);
  const mrsim::test::TempDir tmp;  // removed with the test
  const fs::path& dir = tmp.path();
  fs::create_directories(case_folder(dir, 0));
  write_status(case_folder(dir, 0), {0, "", 1.0});
  write(case_folder(dir, 0) / "summary.json", "{\"final_active\": [9, 4, 77, 1341]}");
  const std::vector<SweepCase> cases{{0, {{"material.lambda", json(0)},
                                          {"material.damping.psi", json(2)}}}};
  const std::string csv =
      results_csv(dir, {"material.lambda", "material.damping.psi"}, cases);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), fixture_header);  // CRLF included
}

TEST(ResultsTable, RowsFromFakeCaseFolders) {
  const mrsim::test::TempDir tmp;  // removed with the test
  const fs::path& dir = tmp.path();
  fs::create_directories(case_folder(dir, 0));
  write_status(case_folder(dir, 0), {0, "", 2.0});
  write(case_folder(dir, 0) / "summary.json",
        R"({"peak_tool_force": null, "max_displacement": 0.0058868, "final_active": [9, 4],
            "wall_time": 0.79, "real_time_factor": 2.5, "force_evaluations": [100, 28],
            "steps": 1024, "splits": 3,
            "merges": 1})");
  fs::create_directories(case_folder(dir, 1));
  write_status(case_folder(dir, 1), {1, "diverged at frame 6, \"badly\"", 0.4});
  fs::create_directories(case_folder(dir, 2));  // interrupted: listed as pending
  fs::create_directories(case_folder(dir, 4));
  write_status(case_folder(dir, 4), {143, "interrupted by SIGTERM", 3.0});  // a time limit
  const std::vector<SweepCase> cases{{0, {{"a", json(5.0e+4)}}},
                                     {1, {{"a", json("cauchy")}}},
                                     {2, {{"a", json(0.1)}}},
                                     {3, {{"a", json(3)}}},
                                     {4, {{"a", json(4)}}}};
  const auto lines = lines_of(results_csv(dir, {"a"}, cases));
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0],
            "case,status,exit_code,message,param:a,peak_tool_force,max_displacement,"
            "final_active_L0,final_active_L1,wall_time,real_time_factor,force_evaluations,steps,"
            "splits,merges");
  EXPECT_EQ(lines[1], "case_0000,done,0,,50000,,0.0058868,9,4,0.79,2.5,128,1024,3,1");
  EXPECT_EQ(lines[2], "case_0001,failed,1,\"diverged at frame 6, \"\"badly\"\"\",cauchy,,,,,,,,,,");
  EXPECT_EQ(lines[3], "case_0002,pending,,,0.1,,,,,,,,,,");
  EXPECT_EQ(lines[4], "case_0003,pending,,,3,,,,,,,,,,");
  EXPECT_EQ(lines[5], "case_0004,interrupted,143,interrupted by SIGTERM,4,,,,,,,,,,");
}

TEST(CaseRunner, FailureMessageIsTheErrorTail) {
  EXPECT_EQ(failure_message("warning: x\nerror: simulation diverged at frame 6\n\n"),
            "simulation diverged at frame 6");
  EXPECT_EQ(failure_message("a\nerror: s.yaml:3:1: bad\ns.yaml:4:1: worse\n"),
            "s.yaml:3:1: bad\ns.yaml:4:1: worse");
  EXPECT_EQ(failure_message("first\nlast line\n"), "last line");
  EXPECT_EQ(failure_message(""), "");
}

TEST(CaseRunner, ChildEnvironmentPassiveUnlessSet) {
  unsetenv("OMP_WAIT_POLICY");
  auto env = child_environment();
  EXPECT_NE(std::find(env.begin(), env.end(), "OMP_WAIT_POLICY=PASSIVE"), env.end());
  setenv("OMP_WAIT_POLICY", "ACTIVE", 1);
  env = child_environment();
  EXPECT_NE(std::find(env.begin(), env.end(), "OMP_WAIT_POLICY=ACTIVE"), env.end());
  EXPECT_EQ(std::find(env.begin(), env.end(), "OMP_WAIT_POLICY=PASSIVE"), env.end());
  setenv("OMP_WAIT_POLICY", "PASSIVE", 1);
}

TEST(CaseRunner, ChildArguments) {
  RunnerOptions options;
  options.executable = "/bin/mrsim";
  options.base = "b.yaml";
  options.threads = 3;
  const auto args = child_arguments(options, {2, "out/case_0002", {"a=1"}});
  EXPECT_EQ(args, (std::vector<std::string>{"/bin/mrsim", "run", "b.yaml", "--set", "a=1", "-o",
                                            "out/case_0002", "--quiet", "--threads", "3"}));
  const auto resumed = child_arguments(options, {2, "out/case_0002", {"a=1"}, true});
  EXPECT_EQ(resumed, (std::vector<std::string>{"/bin/mrsim", "run", "--resume", "out/case_0002",
                                               "--quiet", "--threads", "3"}));
}
