// write_json_file: atomic, indented, numbers that parse back exactly.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/summary_json.hpp"
#include "temp_dir.hpp"

namespace mrsim {
namespace {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(SummaryJson, RoundTripsNumbersExactlyWithTwoSpaceIndent) {
  test::TempDir dir;
  const auto file = dir.path() / "summary.json";
  const double third = 1.0 / 3.0;
  const double tiny = 4.9406564584124654e-324;  // smallest subnormal
  nlohmann::json summary = {{"wall_time", third},
                            {"peak_tool_force", 0.1 + 0.2},
                            {"tiny", tiny},
                            {"steps", 123456789012LL},
                            {"force_evaluations", {1, 2, 3}}};
  write_json_file(file, summary);
  const std::string text = read_text(file);
  EXPECT_NE(text.find("\n  \"steps\": 123456789012"), std::string::npos) << text;
  const auto back = nlohmann::json::parse(text);
  EXPECT_EQ(back["wall_time"].get<double>(), third);
  EXPECT_EQ(back["peak_tool_force"].get<double>(), 0.1 + 0.2);
  EXPECT_EQ(back["tiny"].get<double>(), tiny);
  EXPECT_EQ(back, summary);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "summary.json.tmp"));
}

TEST(SummaryJson, ReplacesAnExistingFile) {
  test::TempDir dir;
  const auto file = dir.path() / "summary.json";
  write_json_file(file, {{"a", 1}});
  write_json_file(file, {{"b", 2}});
  EXPECT_EQ(nlohmann::json::parse(read_text(file)), nlohmann::json({{"b", 2}}));
}

TEST(SummaryJson, FailureThrowsRunErrorAndKeepsThePreviousFile) {
  test::TempDir dir;
  const auto file = dir.path() / "summary.json";
  write_json_file(file, {{"a", 1}});
  // A directory squatting the temporary name makes the write fail, even as root.
  std::filesystem::create_directory(dir.path() / "summary.json.tmp");
  try {
    write_json_file(file, {{"b", 2}});
    FAIL() << "expected RunError";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("summary.json"), std::string::npos) << e.what();
  }
  EXPECT_EQ(nlohmann::json::parse(read_text(file)), nlohmann::json({{"a", 1}}));
}

}  // namespace
}  // namespace mrsim
