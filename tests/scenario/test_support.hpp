#pragma once
// Helpers shared by the scenario tests: files in a private temporary folder and a check
// that a call throws InputError with a given text.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/error.hpp"

namespace mrsim::test {

inline std::filesystem::path source_dir() { return MRSIM_SOURCE_DIR; }

inline std::filesystem::path good_scenario(const std::string& name) {
  return source_dir() / "tests/scenario/good" / name;
}

/// A fresh folder per test, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("mrsim_scenario_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
             std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }

  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto file = path_ / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

 private:
  std::filesystem::path path_;
};

/// The message of the InputError `call` throws; a test failure if it throws nothing else.
inline std::string input_error_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
    return {};
  }
  ADD_FAILURE() << "expected InputError, nothing was thrown";
  return {};
}

}  // namespace mrsim::test

#define EXPECT_INPUT_ERROR(call, text)                                         \
  do {                                                                         \
    const std::string message_ = ::mrsim::test::input_error_of([&] { call; }); \
    EXPECT_NE(message_.find(text), std::string::npos)                          \
        << "message: " << message_ << "\nexpected to contain: " << (text);     \
  } while (0)
