// `--set key.path=value` overrides: applied before validation, validated like the file.
#include "scenario/overrides.hpp"

#include <gtest/gtest.h>

#include "scenario/scenario.hpp"
#include "test_support.hpp"

namespace mrsim {
namespace {

using nlohmann::json;

Scenario load_with(const std::vector<std::string>& sets) {
  return load_scenario(test::good_scenario("minimal.yaml"), sets);
}

TEST(Overrides, ScalarAndNestedValues) {
  const Scenario s = load_with({"material.lambda=7.5e4", "time.substeps=16", "name=other"});
  EXPECT_DOUBLE_EQ(s.material.lambda, 7.5e4);
  EXPECT_EQ(s.time.substeps, 16);
  EXPECT_EQ(s.name, "other");
  EXPECT_EQ(s.output.dir, "out/other");  // the default follows the overridden name
}

// Issue 18 defect 10: `key=null` removes the key, so its default applies again.
TEST(Overrides, NullRemovesTheKey) {
  const Scenario s =
      load_with({"time.substeps=16", "time.substeps=null", "material.damping.psi=null"});
  EXPECT_EQ(s.time.substeps, 0) << "computed from the meshes again";
  EXPECT_DOUBLE_EQ(s.material.psi, 0.0) << "a key that is not there is left alone";
  EXPECT_INPUT_ERROR(load_with({"name=null"}), "name");  // required: the schema says so
  EXPECT_INPUT_ERROR(load_with({"object.levels.0.mesh=null"}), "mesh");
}

// Issue 18 defect 10: an integral float is an integer where the schema asks for one.
TEST(Overrides, IntegralFloatsAreIntegers) {
  EXPECT_EQ(load_with({"time.substeps=512.0"}).time.substeps, 512);
  EXPECT_EQ(load_with({"output.every=2.0e+0"}).output.every, 2);
  EXPECT_INPUT_ERROR(load_with({"time.substeps=512.5"}), "time.substeps");
  EXPECT_DOUBLE_EQ(load_with({"material.lambda=5.0"}).material.lambda, 5.0);  // stays a float
}

TEST(Overrides, CreatesMissingMappings) {
  const Scenario s = load_with({"material.damping.psi=20", "output.vtk=false"});
  EXPECT_DOUBLE_EQ(s.material.psi, 20.0);
  EXPECT_DOUBLE_EQ(s.material.phi, 0.0);
  EXPECT_FALSE(s.output.vtk);
}

TEST(Overrides, ArrayIndexAndSequenceValue) {
  const Scenario s = load_with({"object.levels.0.mesh=/abs/other.vtu", "gravity=[0, 0, 0]",
                                "fixed.0.box={min: [0,0,0], max: [1,1,1]}"});
  EXPECT_EQ(s.levels.at(0).mesh, "/abs/other.vtu");
  EXPECT_EQ(s.gravity, Vec3::Zero());
  ASSERT_EQ(s.fixed.size(), 1u);
  EXPECT_EQ(s.fixed[0].max, Vec3(1, 1, 1));
  EXPECT_EQ(s.resolved["object"]["levels"][0]["mesh"], "/abs/other.vtu");
}

TEST(Overrides, LaterOverridesWin) {
  EXPECT_EQ(load_with({"time.substeps=2", "time.substeps=3"}).time.substeps, 3);
}

TEST(Overrides, InvalidValuesAreReportedAgainstTheOverride) {
  EXPECT_INPUT_ERROR(load_with({"material.lambda=-5"}),
                     "--set material.lambda=-5: material.lambda: must be >= 0 (got -5)");
  EXPECT_INPUT_ERROR(load_with({"gravity=[0,0]"}),
                     "--set gravity=[0,0]: gravity: must have exactly 3 items (got 2)");
  EXPECT_INPUT_ERROR(load_with({"time.substeps=many"}), "must be an integer (got 'many')");
  EXPECT_INPUT_ERROR(load_with({"gravity=[0, 0, .nan]"}), "--set gravity=[0, 0, .nan]: '.nan'");
  EXPECT_INPUT_ERROR(load_with({"gravity=[0, 0"}), "--set gravity=[0, 0: YAML syntax error");
  // Issue 18 defect 3: frame counts no longer wrap (8.589934610e+7 s ran 9 frames).
  EXPECT_INPUT_ERROR(load_with({"time.duration=8.589934610e+7"}),
                     "time.duration: gives 2.15e+09 frames of time.frame_dt 0.04 s; at most "
                     "1.0e+8 frames are run");
  EXPECT_INPUT_ERROR(load_with({"time.frame_dt=1e-300"}), "at most 1.0e+8 frames are run");
  EXPECT_NO_THROW(load_with({"time.duration=4.0e+6"}));  // 1e8 frames of 0.04 s
  // A long value is shortened in the message (issue 18 defect 1), and refused, not a crash.
  EXPECT_INPUT_ERROR(load_with({"name=" + std::string(30000, 'a')}),
                     "--set name=" + std::string(55, 'a') + "… (30005 characters): name: is "
                     "30000 bytes long; at most 4096 are accepted");
}

TEST(Overrides, UnknownPathIsAnUnknownKey) {
  EXPECT_INPUT_ERROR(load_with({"output.evry=2"}),
                     "--set output.evry=2: output.evry: unknown key; did you mean 'every'?");
  EXPECT_INPUT_ERROR(load_with({"materal.lambda=2"}), "did you mean 'material'?");
}

TEST(Overrides, BadPathsAreRejected) {
  EXPECT_INPUT_ERROR(load_with({"name.first=x"}),
                     "--set name.first=x: cannot set 'first' inside name");
  EXPECT_INPUT_ERROR(load_with({"object.levels.3.mesh=x"}),
                     "index 3 is out of range (object.levels has 1 item)");
  EXPECT_INPUT_ERROR(load_with({"object.levels.first.mesh=x"}), "expected an index, got 'first'");
}

TEST(Overrides, MalformedOverridesAreRejected) {
  EXPECT_INPUT_ERROR(load_with({"material.lambda"}),
                     "--set material.lambda: expected key.path=value");
  EXPECT_INPUT_ERROR(load_with({"=5"}), "empty key path");
  EXPECT_INPUT_ERROR(load_with({"material..lambda=5"}), "empty key in path");
  EXPECT_INPUT_ERROR(load_with({"material.lambda="}), "missing value after '='");
}

TEST(Overrides, RecordTheirOriginForLaterMessages) {
  json doc = json::parse(R"({"a": {"b": 1}})");
  scenario::SourceMap positions;
  positions.set("/a/b", {"f.yaml", 3, 5, 0});
  scenario::apply_overrides(doc, positions, {"a.b=[1, 2]", "c.0.d=x"});
  EXPECT_EQ(doc, json::parse(R"({"a": {"b": [1, 2]}, "c": [{"d": "x"}]})"));
  EXPECT_EQ(positions.find("/a/b/1").origin, "--set a.b=[1, 2]");
  EXPECT_EQ(positions.find("/c/0").origin, "--set c.0.d=x");
  EXPECT_EQ(positions.find("/c/0").rank, 2);
}

}  // namespace
}  // namespace mrsim
