// YAML -> JSON through yaml-cpp's event API: types, positions, and every input we refuse.
#include "scenario/yaml_to_json.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace mrsim::scenario {
namespace {

using nlohmann::json;

YamlDocument parse(const std::string& text) { return yaml_to_json(text, {"t.yaml", true, 0}); }
json value_of(const std::string& text) { return parse(text).value; }

TEST(YamlToJson, PlainScalarsFollowTheYaml12CoreSchema) {
  const json v = value_of(
      "a: 1\nb: -2\nc: 1.5\nd: 1.0e5\ne: 1e-3\nf: true\ng: False\nh: ~\ni: null\nj:\n"
      "k: 0x1F\nl: 0o17\nm: yes\nn: on\no: hello world\np: .5\nq: +3\nr: 2.\n");
  EXPECT_EQ(v["a"], 1);
  EXPECT_TRUE(v["a"].is_number_integer());
  EXPECT_EQ(v["b"], -2);
  EXPECT_DOUBLE_EQ(v["c"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(v["d"].get<double>(), 1.0e5);
  EXPECT_TRUE(v["d"].is_number_float());
  EXPECT_DOUBLE_EQ(v["e"].get<double>(), 1e-3);
  EXPECT_EQ(v["f"], true);
  EXPECT_EQ(v["g"], false);
  EXPECT_TRUE(v["h"].is_null());
  EXPECT_TRUE(v["i"].is_null());
  EXPECT_TRUE(v["j"].is_null());
  EXPECT_EQ(v["k"], 31);
  EXPECT_EQ(v["l"], 15);
  EXPECT_EQ(v["m"], "yes");  // YAML 1.1 booleans are strings in 1.2
  EXPECT_EQ(v["n"], "on");
  EXPECT_EQ(v["o"], "hello world");
  EXPECT_DOUBLE_EQ(v["p"].get<double>(), 0.5);
  EXPECT_EQ(v["q"], 3);
  EXPECT_DOUBLE_EQ(v["r"].get<double>(), 2.0);
}

TEST(YamlToJson, QuotedAndTaggedScalars) {
  const json v = value_of("a: \"1\"\nb: '2.5'\nc: !!str true\nd: !!float 3\ne: |\n  text\n");
  EXPECT_EQ(v["a"], "1");
  EXPECT_EQ(v["b"], "2.5");
  EXPECT_EQ(v["c"], "true");
  EXPECT_TRUE(v["d"].is_number_float());
  EXPECT_EQ(v["e"], "text\n");
  EXPECT_INPUT_ERROR(value_of("a: !!int abc\n"), "not a valid !!int");
  EXPECT_INPUT_ERROR(value_of("a: !custom 1\n"), "unsupported YAML tag");
}

// Issue 18 defect 4: yaml-cpp read an unclosed quote to the end of the text and the run went
// on with output.dir = "out/beam every: 1 ".
TEST(YamlToJson, UnterminatedQuotesAreSyntaxErrors) {
  EXPECT_INPUT_ERROR(parse("output:\n  dir: \"out/beam\n  every: 1\n"),
                     "t.yaml:2:8: output.dir: unterminated quoted string: no closing \"");
  EXPECT_INPUT_ERROR(parse("a: 'it''s\nb: 1\n"), "unterminated quoted string: no closing '");
  EXPECT_INPUT_ERROR(parse("a: \"ends in an escaped quote\\\"\n"), "no closing \"");
  EXPECT_EQ(value_of("a: 'it''s \"ok\"'\n")["a"], "it's \"ok\"");
  EXPECT_EQ(value_of("a: \"x\\\"y\"\n")["a"], "x\"y");
  EXPECT_EQ(value_of("a: \"two\n  lines\"\n")["a"], "two lines");
}

TEST(YamlToJson, NestedMappingsAndLists) {
  const json v = value_of("a:\n  b: [1, 2, {c: d}]\n  e:\n    - x\n    - y: 1\n");
  EXPECT_EQ(v, json::parse(R"({"a": {"b": [1, 2, {"c": "d"}], "e": ["x", {"y": 1}]}})"));
}

TEST(YamlToJson, RecordsTheLineAndColumnOfEveryKeyAndItem) {
  const auto doc = parse("name: x\nmaterial:\n  lambda: -5\nlist:\n  - 1\n  - 2\n");
  EXPECT_EQ(doc.positions.at("/name").line, 1);
  EXPECT_EQ(doc.positions.at("/material/lambda").line, 3);
  EXPECT_EQ(doc.positions.at("/material/lambda").column, 3);
  EXPECT_EQ(doc.positions.at("/list/1").line, 6);
  EXPECT_EQ(doc.positions.at("/list/1").column, 5);
  EXPECT_EQ(doc.positions.find("/material/mu").line, 2);  // nearest ancestor
}

TEST(YamlToJson, DuplicateKeysAreRejectedWithBothLines) {
  const std::string message = test::input_error_of([] { parse("a: 1\nb:\n  c: 1\n  c: 2\n"); });
  EXPECT_NE(message.find("t.yaml:4:3: b.c: duplicate key (first defined at line 3:3)"),
            std::string::npos)
      << message;
  EXPECT_INPUT_ERROR(parse("{a: 1, a: 2}\n"), "duplicate key");
}

TEST(YamlToJson, AliasesCopyTheAnchoredValue) {
  const json v = value_of("base: &b {x: 1, y: [1, 2]}\ncopy: *b\nscalar: &s 7\nagain: *s\n");
  EXPECT_EQ(v["copy"], v["base"]);
  EXPECT_EQ(v["again"], 7);
}

TEST(YamlToJson, RecursiveAliasIsRejected) {
  EXPECT_INPUT_ERROR(parse("a: &x [1, *x]\n"), "t.yaml:1:11: a.1: recursive alias *x");
  EXPECT_INPUT_ERROR(parse("a: &m\n  b: *m\n"), "t.yaml:2:6: a.b: recursive alias *m");
}

TEST(YamlToJson, AliasExpansionIsBounded) {
  std::string text = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < 8; ++i) {
    const std::string prev = "*a" + std::to_string(i - 1);
    const std::string name = std::to_string(i);  // appended piecewise: GCC 12 -Wrestrict false positive
    text.append("a").append(name).append(": &a").append(name).append(" [");
    for (int k = 0; k < 10; ++k) text += (k ? ", " : "") + prev;
    text += "]\n";
  }
  EXPECT_INPUT_ERROR(parse(text), "too large");
}

TEST(YamlToJson, NestingDepthIsBounded) {
  EXPECT_INPUT_ERROR(parse(std::string(100, '[') + std::string(100, ']') + "\n"),
                     "nesting deeper than");
  EXPECT_NO_THROW(parse(std::string(20, '[') + std::string(20, ']') + "\n"));
}

TEST(YamlToJson, NonFiniteNumbersAreRejected) {
  EXPECT_INPUT_ERROR(parse("a: .nan\n"), "t.yaml:1:4: a: '.nan' is not a finite number");
  EXPECT_INPUT_ERROR(parse("a: -.inf\n"), "not a finite number");
  EXPECT_INPUT_ERROR(parse("a: 1e999\n"), "out of range");
  EXPECT_INPUT_ERROR(parse("a: 99999999999999999999\n"), "out of range");
  EXPECT_EQ(value_of("a: '.nan'\n")["a"], ".nan");  // quoted: a string, fine
}

TEST(YamlToJson, KeysMustBeStrings) {
  EXPECT_INPUT_ERROR(parse("1: a\n"),
                     "t.yaml:1:1: (document): mapping keys must be strings (got 1)");
  EXPECT_INPUT_ERROR(parse("? [1]\n: a\n"), "mapping keys must be strings (got a list)");
  EXPECT_INPUT_ERROR(parse("? {a: 1}\n: a\n"), "mapping keys must be strings (got a mapping)");
  EXPECT_INPUT_ERROR(parse("true: a\n"), "mapping keys must be strings");
  EXPECT_INPUT_ERROR(parse(": a\n"), "mapping keys must be strings (got an empty key)");
  EXPECT_EQ(value_of("'1': a\n")["1"], "a");
}

TEST(YamlToJson, SyntaxErrorsNameLineAndColumn) {
  EXPECT_INPUT_ERROR(parse("a:\n\tb: 1\n"), "t.yaml:2:3: YAML syntax error");
  EXPECT_INPUT_ERROR(parse("a: [1, 2\nb: 3\n"),
                     "YAML syntax error: end of sequence flow not found");
  EXPECT_INPUT_ERROR(parse("a: *nothing\n"), "t.yaml:1:4: YAML syntax error");
}

TEST(YamlToJson, InputThatMakesYamlCppLoopIsASyntaxError) {
  // yaml-cpp 0.7 starts empty documents forever on a ',' in column 1 of a block.
  EXPECT_INPUT_ERROR(parse("# c\n, x\na: 1\n"), "t.yaml:2:1: YAML syntax error");
}

TEST(YamlToJson, EmptyAndMultipleDocumentsAreRejected) {
  EXPECT_INPUT_ERROR(parse(""), "t.yaml: empty YAML document");
  EXPECT_INPUT_ERROR(parse("# only a comment\n"), "empty YAML document");
  EXPECT_INPUT_ERROR(parse("---\n"), "empty YAML document");
  EXPECT_INPUT_ERROR(parse("a: 1\n---\nb: 2\n"),
                     "t.yaml:2:1: a scenario holds a single YAML document");
}

TEST(YamlToJson, WithoutPositionsMessagesNameOnlyTheOrigin) {
  const std::string message = test::input_error_of([] {
    yaml_to_json("[1, .nan]", {"--set g=[1, .nan]", false, 1});
  });
  EXPECT_EQ(message.rfind("--set g=[1, .nan]: '.nan'", 0), 0u) << message;
}

}  // namespace
}  // namespace mrsim::scenario
