// Schema validation messages: key paths, line:column, did-you-mean, several problems at once.
#include "scenario/schema_validator.hpp"

#include <gtest/gtest.h>

#include "scenario/schema.hpp"
#include "scenario/yaml_to_json.hpp"
#include "test_support.hpp"

namespace mrsim::scenario {
namespace {

using nlohmann::json;

void validate_text(const std::string& yaml) {
  const auto doc = yaml_to_json(yaml, {"s.yaml", true, 0});
  validate_against_schema(doc.value, doc.positions);
}

const std::string kHead =
    "name: t\n"
    "object:\n"
    "  levels:\n"
    "    - mesh: a.vtu\n";

TEST(SchemaValidator, MinimalDocumentIsValid) {
  EXPECT_NO_THROW(validate_text(kHead + "material: {lambda: 1, mu: 1}\n"));
  EXPECT_NO_THROW(validate_text(kHead + "material: {youngs_modulus: 1, poisson_ratio: 0}\n"));
}

TEST(SchemaValidator, MessagesNameFileLineColumnAndKeyPath) {
  EXPECT_INPUT_ERROR(validate_text(kHead + "material:\n  mu: 1\n  lambda: -5\n"),
                     "s.yaml:7:3: material.lambda: must be >= 0 (got -5)");
  EXPECT_INPUT_ERROR(validate_text(kHead + "material: {lambda: 1, mu: 1}\noutput:\n  evry: 2\n"),
                     "s.yaml:7:3: output.evry: unknown key; did you mean 'every'?");
  EXPECT_INPUT_ERROR(validate_text(kHead + "material: {lambda: 1, mu: 1}\ntime: {frame_dt: 0}\n"),
                     "s.yaml:6:8: time.frame_dt: must be > 0 (got 0)");
}

// Issue 18 defect 1: valijson matches `pattern` with std::regex, which recursed once per
// character; a 30 000-character name segfaulted. Long strings are now an input error.
TEST(SchemaValidator, LongStringsAreAnIssueNotACrash) {
  const std::string name(30000, 'a');
  EXPECT_INPUT_ERROR(validate_text("name: " + name +
                                   "\nobject:\n  levels:\n    - mesh: a.vtu\n"
                                   "material: {lambda: 1, mu: 1}\n"),
                     "s.yaml:1:1: name: is 30000 bytes long; at most 4096 are accepted");
  const std::string dir(4097, 'd');
  EXPECT_INPUT_ERROR(
      validate_text(kHead + "material: {lambda: 1, mu: 1}\noutput: {dir: " + dir + "}\n"),
      "output.dir: is 4097 bytes long; at most 4096 are accepted");
  // A long free-text description is fine, and 4096 bytes still are.
  EXPECT_NO_THROW(validate_text(
      "description: " + std::string(60000, 'x') + "\n" + kHead +
      "material: {lambda: 1, mu: 1}\noutput: {dir: " + std::string(4096, 'd') + "}\n"));
}

// Issue 18 defect 10: inside a oneOf (the tool shapes), a fault of the chosen branch is said in
// its own words; valijson's text for every other branch ("Missing required property
// 'capsule'") is not shown.
TEST(SchemaValidator, FaultsInsideTheChosenOneOfBranchAreDescribedAlone) {
  const std::string head = kHead + "material: {lambda: 1, mu: 1}\ntool:\n  shape: ";
  const std::string tail = "\n  trajectory:\n    - {t: 0, position: [0, 0, 0]}\n";
  auto message = [&](const std::string& shape) {
    return test::input_error_of([&] { validate_text(head + shape + tail); });
  };
  const std::string radius = message("{sphere: {radius: 0}}");
  EXPECT_NE(radius.find("s.yaml:7:20: tool.shape.sphere.radius: must be > 0 (got 0)"),
            std::string::npos)
      << radius;
  const std::string length = message("{capsule: {radius: 0.01}}");
  EXPECT_NE(length.find("tool.shape.capsule.length: required key is missing"), std::string::npos)
      << length;
  const std::string unknown = message("{flat_cylinder: {radius: 0.01, length: 0.1, heigth: 1}}");
  EXPECT_NE(unknown.find("tool.shape.flat_cylinder.heigth: unknown key"), std::string::npos)
      << unknown;
  for (const std::string& m : {radius, length, unknown}) {
    EXPECT_EQ(m.find("Missing required property"), std::string::npos) << m;
    EXPECT_EQ(m.find("could not be validated"), std::string::npos) << m;
  }
  // Two shapes, or none, are still named as the choice.
  EXPECT_NE(message("{sphere: {radius: 0.01}, capsule: {radius: 0.01, length: 0.1}}")
                .find("give exactly one of sphere, capsule or flat_cylinder, not several"),
            std::string::npos);
}

// Issue 18 defect 9: a NUL or invalid UTF-8 in a text was copied into every output.
TEST(SchemaValidator, TextIsValidUtf8WithoutControlCharacters) {
  const std::string tail = kHead + "material: {lambda: 1, mu: 1}\n";
  EXPECT_INPUT_ERROR(validate_text("description: \"a\\0b\"\n" + tail),
                     "description: contains the control character 0 at byte 1");
  EXPECT_INPUT_ERROR(validate_text("description: \"caf\xC3\"\n" + tail),
                     "description: is not valid UTF-8 (byte 3)");
  EXPECT_INPUT_ERROR(validate_text("description: \"\xED\xA0\x80\"\n" + tail),
                     "is not valid UTF-8 (byte 0)");  // a surrogate
  EXPECT_NO_THROW(
      validate_text("description: \"caf\xC3\xA9 \xE2\x86\x92 \xF0\x9F\x98\x80\tok\"\n" + tail));
}

TEST(SchemaValidator, UnknownKeyWithoutCloseMatchListsTheKnownKeys) {
  EXPECT_INPUT_ERROR(validate_text(kHead + "material: {lambda: 1, mu: 1}\noutput: {zzz: 1}\n"),
                     "output.zzz: unknown key; expected one of: checkpoint_every, compression, dir, every, vtk");
}

TEST(SchemaValidator, AllProblemsAreReportedInSourceOrder) {
  const std::string message = test::input_error_of(
      [] { validate_text(kHead + "material: {lambda: 1, mu: 1, density: 0}\ngravity: [0, 0]\n"); });
  const auto density = message.find("material.density: must be > 0");
  const auto gravity = message.find("gravity: must have exactly 3 items");
  ASSERT_NE(density, std::string::npos) << message;
  ASSERT_NE(gravity, std::string::npos) << message;
  EXPECT_LT(density, gravity);
}

TEST(SchemaValidator, ResolvedDocumentWithDerivedConstantsIsValid) {
  json doc = yaml_to_json(kHead + "material: {lambda: 1, mu: 1}\n", {"s", true, 0}).value;
  doc["material"]["derived"] = {
      {"lambda", 1}, {"mu", 1}, {"youngs_modulus", 2.5}, {"poisson_ratio", 0.25}};
  EXPECT_TRUE(schema_issues(doc).empty());
}

TEST(Schema, EmbeddedSchemaIsTheSourceFile) {
  std::ifstream in(test::source_dir() / "schemas/scenario.schema.json");
  const json on_disk = json::parse(in);
  EXPECT_EQ(scenario_schema(), on_disk);  // a stale build would embed an older schema
}

TEST(Schema, PropertyOrderFollowsTheSchemaFile) {
  const auto& order = property_order();
  auto at = [&](const std::string& k) { return std::find(order.begin(), order.end(), k); };
  EXPECT_EQ(order.front(), "name");
  EXPECT_LT(at("object"), at("material"));
  EXPECT_LT(at("lambda"), at("mu"));
  EXPECT_LT(at("time"), at("output"));
}

}  // namespace
}  // namespace mrsim::scenario
