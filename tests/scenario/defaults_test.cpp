// Schema defaults are injected recursively and the result still validates.
#include "scenario/defaults.hpp"

#include <gtest/gtest.h>

#include "scenario/schema_validator.hpp"

namespace mrsim::scenario {
namespace {

using nlohmann::json;

json minimal() {
  return json::parse(R"({"name": "m", "object": {"levels": [{"mesh": "a.vtu"}]},
                         "material": {"lambda": 1, "mu": 2}})");
}

TEST(Defaults, EveryDefaultOfTheSchemaIsInjected) {
  json doc = minimal();
  inject_defaults(doc);
  EXPECT_EQ(doc["object"]["units"], "m");
  EXPECT_EQ(doc["material"]["model"], "green_lagrange");
  EXPECT_EQ(doc["material"]["density"], 1000);
  EXPECT_EQ(doc["material"]["damping"], json::parse(R"({"phi": 0, "psi": 0})"));
  EXPECT_EQ(doc["fixed"], json::array());
  EXPECT_EQ(doc["gravity"], json::parse("[0, 0, -9.81]"));
  EXPECT_EQ(doc["initial"]["velocity"], json::parse("[0, 0, 0]"));
  EXPECT_EQ(doc["initial"]["angular_velocity"], json::parse("[0, 0, 0]"));
  EXPECT_EQ(doc["time"]["integrator"], "modified_euler");
  EXPECT_DOUBLE_EQ(doc["time"]["frame_dt"].get<double>(), 0.04);
  EXPECT_FALSE(doc["time"].contains("substeps"));  // computed from the meshes by the run
  EXPECT_DOUBLE_EQ(doc["time"]["courant"].get<double>(), 1.0);
  EXPECT_EQ(doc["time"]["adapt_substeps"], true);
  EXPECT_DOUBLE_EQ(doc["time"]["duration"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(doc["time"]["divergence"]["energy_factor"].get<double>(), 1.0);
  EXPECT_EQ(doc["output"]["every"], 1);
  EXPECT_EQ(doc["output"]["vtk"], true);
}

TEST(Defaults, GivenValuesAreKeptAndNothingWithoutDefaultIsInvented) {
  json doc = minimal();
  doc["time"] = {{"substeps", 8}};
  doc["output"] = {{"dir", "x"}};
  inject_defaults(doc);
  EXPECT_EQ(doc["time"]["substeps"], 8);
  EXPECT_EQ(doc["time"]["integrator"], "modified_euler");
  EXPECT_EQ(doc["output"]["dir"], "x");
  EXPECT_FALSE(doc.contains("description"));
  EXPECT_FALSE(doc["material"].contains("derived"));  // no default inside: not created
  EXPECT_FALSE(doc["material"].contains("youngs_modulus"));
}

TEST(Defaults, ResultStillValidates) {
  json doc = minimal();
  inject_defaults(doc);
  EXPECT_TRUE(schema_issues(doc).empty());
  const json once = doc;
  inject_defaults(doc);
  EXPECT_EQ(doc, once);  // idempotent
}

}  // namespace
}  // namespace mrsim::scenario
