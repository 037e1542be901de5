#pragma once
// Test helpers shared by every suite: where the shared data lives (tests skip when it is absent)
// and a fresh per-test scratch folder removed afterwards.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace mrsim::test {

namespace fs = std::filesystem;

inline fs::path source_dir() { return fs::path(MRSIM_SOURCE_DIR); }
inline fs::path shared_data() { return fs::path(MRSIM_SHARED_DIR) / "data"; }

#define MRSIM_REQUIRE_SHARED_DATA()                                                \
  do {                                                                             \
    if (!std::filesystem::exists(::mrsim::test::shared_data()))                    \
      GTEST_SKIP() << "shared data not found at " << ::mrsim::test::shared_data(); \
  } while (0)

class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = "mrsim_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
                       std::to_string(::getpid());
    std::replace(name.begin(), name.end(), '/', '_');  // parameterized tests: "Suite/Test/3"
    path_ = fs::temp_directory_path() / name;
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }
  fs::path file(const std::string& name) const { return path_ / name; }
  fs::path write(const std::string& name, const std::string& contents) const {
    std::ofstream(path_ / name, std::ios::binary) << contents;
    return path_ / name;
  }

 private:
  fs::path path_;
};

}  // namespace mrsim::test
