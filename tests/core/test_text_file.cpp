// Whole small files (core/text_file.hpp): every byte back, NULs and a missing newline included,
// from a regular file read in one sized call and from a pipe read as it comes; "" for a file
// that is not there.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "core/text_file.hpp"

using namespace mrsim;

namespace {

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("mrsim_text_file_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

std::string some_bytes() {
  std::string bytes;
  for (int i = 0; i < 100000; ++i) bytes.push_back(static_cast<char>(i * 7 % 256));
  return bytes + "no newline at the end";
}

}  // namespace

TEST(TextFile, ARegularFileComesBackByteForByte) {
  const auto file = scratch("bytes.bin");
  const std::string bytes = some_bytes();
  std::ofstream(file, std::ios::binary) << bytes;
  EXPECT_EQ(read_text_if_any(file), bytes);
  std::ofstream(file, std::ios::binary | std::ios::trunc).flush();
  EXPECT_EQ(read_text_if_any(file), "");
  std::filesystem::remove_all(file.parent_path());
}

TEST(TextFile, APipeIsReadAsItComes) {
  const auto fifo = scratch("fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string bytes = some_bytes();
  std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << bytes; });
  const std::string read = read_text_if_any(fifo);
  writer.join();
  EXPECT_EQ(read, bytes);
  std::filesystem::remove_all(fifo.parent_path());
}

TEST(TextFile, AMissingFileIsEmpty) {
  EXPECT_EQ(read_text_if_any(scratch("absent")), "");
}
