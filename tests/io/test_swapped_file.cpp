// SwappedFile: frames.pvd replaced whole after every frame, by trading names with a spare.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "io/swapped_file.hpp"
#include "temp_dir.hpp"

namespace mrsim {
namespace {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

ino_t inode(const std::filesystem::path& file) {
  struct stat st {};
  EXPECT_EQ(::stat(file.c_str(), &st), 0) << file;
  return st.st_ino;
}

TEST(SwappedFile, EachWriteIsTheWholeFileAndTheSpareHoldsThePrevious) {
  test::TempDir dir;
  const auto file = dir.path() / "frames.pvd";
  SwappedFile pvd(file);
  pvd.write("first, the longest text of all");
  EXPECT_EQ(read_text(file), "first, the longest text of all");
  pvd.write("second");
  EXPECT_EQ(read_text(file), "second");
  EXPECT_EQ(read_text(pvd.spare()), "first, the longest text of all");
  pvd.write("third, longer than the second");  // written over the longer first, then cut
  EXPECT_EQ(read_text(file), "third, longer than the second");
  EXPECT_EQ(read_text(pvd.spare()), "second");
}

// From the second write on, the same two files trade names: no file is created or removed per
// write (what cost a frame an inode and, on ext4, writing the replaced data out).
TEST(SwappedFile, TheSameTwoFilesServeEveryWrite) {
  test::TempDir dir;
  const auto file = dir.path() / "frames.pvd";
  SwappedFile pvd(file);
  pvd.write("0");
  pvd.write("1");
  const std::set<ino_t> two = {inode(file), inode(pvd.spare())};
  ASSERT_EQ(two.size(), 2u);
  for (int k = 2; k < 10; ++k) {
    pvd.write(std::to_string(k));
    EXPECT_EQ((std::set<ino_t>{inode(file), inode(pvd.spare())}), two) << "write " << k;
    EXPECT_EQ(read_text(file), std::to_string(k));
  }
}

TEST(SwappedFile, TheSpareIsRemovedWithTheWriterAndAStaleOneIsOverwritten) {
  test::TempDir dir;
  const auto file = dir.path() / "frames.pvd";
  {
    std::ofstream(file.string() + ".spare") << "a stale spare left by a killed run, long";
    SwappedFile pvd(file);
    pvd.write("new");
    EXPECT_EQ(read_text(file), "new");
    pvd.write("newer");
    EXPECT_EQ(read_text(file), "newer");
  }
  EXPECT_FALSE(std::filesystem::exists(file.string() + ".spare"));
  EXPECT_EQ(read_text(file), "newer");
}

TEST(SwappedFile, FailureThrowsRunErrorNamingTheFile) {
  test::TempDir dir;
  const auto file = dir.path() / "missing" / "frames.pvd";
  SwappedFile pvd(file);
  try {
    pvd.write("text");
    FAIL() << "no error";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mrsim
