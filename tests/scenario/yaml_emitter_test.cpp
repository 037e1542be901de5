// The resolved YAML: numbers and strings read back identically, block layout.
#include "scenario/yaml_emitter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "scenario/yaml_to_json.hpp"

namespace mrsim::scenario {
namespace {

using nlohmann::json;

json reread(const std::string& yaml) { return yaml_to_json(yaml, {"r", true, 0}).value; }

TEST(YamlEmitter, FloatsAlwaysHaveADotAndASignedExponent) {
  EXPECT_EQ(yaml_float(1.0e5), "1.0e+5");
  EXPECT_EQ(yaml_float(1000.0), "1000.0");
  EXPECT_EQ(yaml_float(0.04), "0.04");
  EXPECT_EQ(yaml_float(-9.81), "-9.81");
  EXPECT_EQ(yaml_float(2.5e-7), "2.5e-7");
  EXPECT_EQ(yaml_float(0.0), "0.0");
  EXPECT_EQ(yaml_float(1e300), "1.0e+300");
  EXPECT_THROW(yaml_float(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

// Issue 18 defect 1: strings and numbers of tens of thousands of characters are emitted and
// read back (std::regex, which recursed once per character, overflowed the stack).
TEST(YamlEmitter, LongScalarsDoNotOverflowTheStack) {
  const std::string words = std::string(60000, 'a') + " b/" + std::string(60000, 'c');
  const json doc = {{"description", words}, {"digits", std::string(60000, '7')}};
  const std::string yaml = to_block_yaml(doc);
  EXPECT_EQ(yaml.rfind("description: aaa", 0), 0u) << "plain, not quoted";
  EXPECT_EQ(reread(yaml)["description"], words);
  EXPECT_EQ(reread(yaml)["digits"], std::string(60000, '7')) << "quoted: it would read as a number";
  EXPECT_EQ(reread("x: 1.5e+3\n")["x"], 1500.0);
  EXPECT_EQ(reread("x: .5\n")["x"], 0.5);
  EXPECT_EQ(reread("x: 5.\n")["x"], 5.0);
  EXPECT_EQ(reread("x: 0x1F\n")["x"], 31);
  EXPECT_EQ(reread("x: 0o17\n")["x"], 15);
  EXPECT_EQ(reread("x: 1.2.3\n")["x"], "1.2.3");
  EXPECT_EQ(reread("x: 1e\n")["x"], "1e");
  EXPECT_EQ(reread("x: ./a b\n")["x"], "./a b");
}

TEST(YamlEmitter, FloatsRoundTripExactly) {
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> mantissa(-10, 10);
  std::uniform_int_distribution<int> exponent(-300, 300);
  for (int i = 0; i < 2000; ++i) {
    const double x = std::ldexp(mantissa(random), exponent(random));
    const json back = reread("x: " + yaml_float(x) + "\n")["x"];
    ASSERT_TRUE(back.is_number_float()) << yaml_float(x);
    ASSERT_EQ(back.get<double>(), x) << yaml_float(x);
  }
}

TEST(YamlEmitter, StringsThatLookLikeOtherTypesAreQuoted) {
  for (const std::string s :
       {"1",     "1.5",  "true", "yes",         "No",     "on",      "null",  "~",
        "",      ".inf", "-x",   "a: b",        "#c",     "x #y",    " lead", "trail ",
        "\"q\"", "it's", "[a]",  "line\nbreak", "*alias", "&anchor", "0x10",  "1e5"}) {
    const std::string text = yaml_string(s);
    EXPECT_EQ(text.front(), '"') << s;
    EXPECT_EQ(reread("k: " + text + "\n")["k"], s) << text;
  }
  EXPECT_EQ(yaml_string("liver_probe"), "liver_probe");
  EXPECT_EQ(yaml_string("meshes/cube L0.vtu"), "meshes/cube L0.vtu");
  EXPECT_EQ(yaml_string("/abs/path.vtu"), "/abs/path.vtu");
  EXPECT_EQ(yaml_string("../meshes/a.vtu"), "../meshes/a.vtu");
  EXPECT_EQ(yaml_string("./a.vtu"), "./a.vtu");
  EXPECT_EQ(yaml_string(".5"), "\".5\"");
}

TEST(YamlEmitter, BlockLayoutWithFlowVectors) {
  const json doc = json::parse(R"({"name": "x", "gravity": [0, 0, -9.81], "empty": [],
      "fixed": [{"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}, {"ids": [1, 2]}],
      "time": {"frame_dt": 0.04, "substeps": 64, "vtk": true}, "o": {}})");
  const std::string yaml = to_block_yaml(doc, {"name", "time", "gravity"});
  EXPECT_EQ(yaml,
            "name: x\n"
            "time:\n"
            "  frame_dt: 0.04\n"
            "  substeps: 64\n"
            "  vtk: true\n"
            "gravity: [0, 0, -9.81]\n"
            "empty: []\n"
            "fixed:\n"
            "  - box:\n"
            "      max: [1, 1, 1]\n"
            "      min: [0, 0, 0]\n"
            "  - ids: [1, 2]\n"
            "o: {}\n");
  EXPECT_EQ(reread(yaml), doc);
}

}  // namespace
}  // namespace mrsim::scenario
