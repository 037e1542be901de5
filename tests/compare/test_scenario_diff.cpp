// Resolved scenarios compared as data: output.dir left out, a changed key named by its path,
// keys on one side only, integers exact, malformed YAML an input error.
#include <gtest/gtest.h>

#include "compare/scenario_diff.hpp"
#include "compare/summary_diff.hpp"
#include "core/error.hpp"

namespace mrsim {
namespace {

const char* const kScenario = R"(name: beam
material:
  model: green_lagrange
  lambda: 5.0e+4
  mu: 1.0e+4
gravity: [0, 0, -9.81]
time:
  substeps: 1024
output:
  dir: out/a
  every: 1
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

JsonDiff diff(const std::string& a, const std::string& b, Tolerance t = {}) {
  return diff_scenarios({a, "a.yaml"}, {b, "b.yaml"}, t);
}

TEST(ScenarioDiff, IgnoresOutputDir) {
  const JsonDiff d = diff(kScenario, replaced(kScenario, "out/a", "/elsewhere/b"));
  EXPECT_TRUE(d.differences.empty());
  EXPECT_EQ(d.ignored, std::vector<std::string>{"output.dir"});
  EXPECT_GT(d.compared, 5u);
}

TEST(ScenarioDiff, NamesAChangedKeyWithBothValues) {
  const JsonDiff d = diff(kScenario, replaced(kScenario, "lambda: 5.0e+4", "lambda: 6.0e+4"));
  ASSERT_EQ(d.differences.size(), 1u);
  EXPECT_EQ(d.differences[0].path, "material.lambda");
  EXPECT_EQ(d.differences[0].a, "50000");
  EXPECT_EQ(d.differences[0].b, "60000");
}

TEST(ScenarioDiff, NumbersWithinToleranceIntegersExact) {
  const std::string b =
      replaced(replaced(kScenario, "lambda: 5.0e+4", "lambda: 5.0001e+4"), "1024", "1025");
  const JsonDiff d = diff(kScenario, b, {1e-3, 0});
  ASSERT_EQ(d.differences.size(), 1u);
  EXPECT_EQ(d.differences[0].path, "time.substeps");
  EXPECT_EQ(diff(kScenario, replaced(kScenario, "-9.81]", "-9.8]")).differences.at(0).path,
            "gravity.2");
}

TEST(ScenarioDiff, KeysOnOneSideOnly) {
  const JsonDiff d = diff(kScenario, replaced(kScenario, "  mu: 1.0e+4\n", ""));
  ASSERT_EQ(d.differences.size(), 1u);
  EXPECT_EQ(d.differences[0].path, "material.mu");
  EXPECT_EQ(d.differences[0].b, "(missing)");
}

TEST(ScenarioDiff, MalformedYamlIsAnInputErrorNamingTheOrigin) {
  try {
    diff(kScenario, "name: [unclosed\n");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("b.yaml"), std::string::npos) << e.what();
  }
}

TEST(SummaryDiff, IgnoresWallTimesAndBuild) {
  const nlohmann::json a = {{"frames", 10},
                            {"wall_time", 1.5},
                            {"mrsim_version", "0.1.0"},
                            {"max_displacement", 0.01},
                            {"force_evaluations", {100, 200}}};
  nlohmann::json b = a;
  b["wall_time"] = 9.0;
  b["real_time_factor"] = 0.2;  // a time too: only in b, or another value, is no difference
  b["mrsim_version"] = "0.2.0";
  b["force_kernel"] = "avx512";  // another machine: the same results
  EXPECT_TRUE(diff_summaries(a, b, {}).differences.empty());
  b["force_evaluations"][1] = 201;
  const JsonDiff d = diff_summaries(a, b, {1.0, 1.0});
  ASSERT_EQ(d.differences.size(), 1u);
  EXPECT_EQ(d.differences[0].path, "force_evaluations.1");
  EXPECT_TRUE(is_ignored_summary_key("wall_time"));
  EXPECT_TRUE(is_ignored_summary_key("real_time_factor"));
  EXPECT_FALSE(is_ignored_summary_key("frames"));
}

}  // namespace
}  // namespace mrsim
