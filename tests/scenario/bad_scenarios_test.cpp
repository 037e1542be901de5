// The corpus tests/scenario/bad/*.yaml: each file's first line is "# expect: <text>" and
// loading it must throw InputError whose message contains <text>.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "scenario/scenario.hpp"
#include "test_support.hpp"

namespace mrsim {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> corpus() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(test::source_dir() / "tests/scenario/bad"))
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string expectation(const fs::path& file) {
  std::ifstream in(file);
  std::string first;
  std::getline(in, first);
  const std::string tag = "# expect: ";
  return first.rfind(tag, 0) == 0 ? first.substr(tag.size()) : std::string{};
}

TEST(BadScenarios, CorpusHasAtLeastTwentyFiles) { EXPECT_GE(corpus().size(), 20u); }

TEST(BadScenarios, EachIsRejectedWithItsExpectedMessage) {
  for (const auto& file : corpus()) {
    SCOPED_TRACE(file.filename().string());
    const std::string expected = expectation(file);
    ASSERT_FALSE(expected.empty()) << "first line must be '# expect: <text>'";
    EXPECT_INPUT_ERROR(load_scenario(file), expected);
  }
}

}  // namespace
}  // namespace mrsim
