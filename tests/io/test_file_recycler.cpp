// FileRecycler and RunFolder: a run into a folder holding a finished run writes its frames over
// the old run's files, with the bytes a run into a new folder writes, and leaves nothing stale.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "io/file_recycler.hpp"
#include "io/run_folder.hpp"
#include "io/vtk_series_writer.hpp"
#include "sample_frames.hpp"
#include "temp_dir.hpp"

namespace mrsim {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every file under `dir`, by its path relative to `dir`, with its bytes.
std::map<std::string, std::string> tree(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file())
      files[fs::relative(entry.path(), dir).generic_string()] = read_text(entry.path());
  return files;
}

std::set<ino_t> inodes(const fs::path& dir) {
  std::set<ino_t> found;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    struct stat st {};
    EXPECT_EQ(::lstat(entry.path().c_str(), &st), 0);
    found.insert(st.st_ino);
  }
  return found;
}

// `frames` frames of the sample levels from frame `first` on (their data differ by frame).
void write_series(const fs::path& dir, int first, int frames, std::size_t* recycled = nullptr) {
  VtkSeriesWriter writer(dir);
  for (int f = 0; f < frames; ++f) {
    const auto levels = test::sample_frame((first + f) % 3);
    writer.write_frame(f, 0.04 * f, test::views_of(levels));
  }
  if (recycled != nullptr) *recycled = writer.recycled_files();
}

// What RunFolder does to a finished run's folder before the new run writes.
void take_over(const fs::path& dir) { fs::rename(dir / "frames", dir / "frames.recycled"); }

TEST(FileRecycler, ANewSeriesWritesOverTheOldFilesWithTheBytesOfAFreshOne) {
  for (const int frames : {2, 3, 5}) {  // fewer, as many and more frames than the old series
    test::TempDir tmp;  // one per test: two folders in it
    const fs::path reused = tmp.path() / "reused", fresh = tmp.path() / "fresh";
    write_series(reused, 1, 3);
    const std::set<ino_t> old = inodes(reused / "frames");
    take_over(reused);
    std::size_t recycled = 0;
    write_series(reused, 0, frames, &recycled);
    write_series(fresh, 0, frames);
    EXPECT_EQ(tree(reused / "frames"), tree(fresh / "frames")) << frames;
    EXPECT_EQ(read_text(reused / "frames.pvd"), read_text(fresh / "frames.pvd"));
    // Each frame: one .vtm and two pieces; the old series had 3 frames, 9 files, 3 folders.
    EXPECT_EQ(recycled, static_cast<std::size_t>(3 * std::min(frames, 3))) << frames;
    if (frames <= 3) {  // every file and frame folder is an old one (frames/ itself is new)
      for (const auto& entry : fs::recursive_directory_iterator(reused / "frames")) {
        struct stat st {};
        ::lstat(entry.path().c_str(), &st);
        EXPECT_TRUE(old.count(st.st_ino)) << entry.path() << ": new, not an old one";
      }
    }
  }
}

// A frame kept under another name (cp -al) or a link to a user's file is never written over.
TEST(FileRecycler, FilesLinkedElsewhereAreLeftAsTheyWere) {
  test::TempDir tmp;
  const fs::path dir = tmp.path() / "run", kept = tmp.path() / "kept";
  write_series(dir, 1, 2);
  fs::create_directories(kept);
  const fs::path piece = dir / "frames" / "frame_000000" / "frame_000000_0.vtu";
  const std::string before = read_text(piece);
  fs::create_hard_link(piece, kept / "kept.vtu");
  std::ofstream(kept / "mine.txt") << "the user's own file";
  fs::create_symlink(kept / "mine.txt", dir / "frames" / "frame_000001.vtm.link");
  take_over(dir);
  write_series(dir, 0, 2);
  EXPECT_EQ(read_text(kept / "kept.vtu"), before);
  EXPECT_EQ(read_text(kept / "mine.txt"), "the user's own file");
  struct stat st {};
  ASSERT_EQ(::lstat((kept / "kept.vtu").c_str(), &st), 0);
  EXPECT_EQ(st.st_nlink, 2u);  // its other name is still in the pool, not in the new frames
  for (const auto& entry : fs::recursive_directory_iterator(dir / "frames")) {
    struct stat now {};
    ::lstat(entry.path().c_str(), &now);
    EXPECT_NE(now.st_ino, st.st_ino) << entry.path();
  }
}

TEST(FileRecycler, NothingToReuseMakesNewFiles) {
  test::TempDir dir;
  FileRecycler recycler(dir.path() / "absent");
  recycler.make_directory(dir.path() / "d");
  recycler.write_file(dir.path() / "d" / "f", "bytes");
  EXPECT_EQ(read_text(dir.path() / "d" / "f"), "bytes");
  EXPECT_EQ(recycler.reused(), 0u);
}

// RunFolder hands the old frames over under frames.recycled and removes what is left of them
// when the run ends; a killed run's leftover goes first.
TEST(RunFolder, TheOldFramesAreKeptForTheRunThenRemoved) {
  test::TempDir dir;
  write_series(dir.path(), 0, 2);
  fs::create_directories(dir.path() / "frames.recycled" / "stale");
  {
    RunFolder folder(dir.path(), {});
    EXPECT_FALSE(fs::exists(dir.path() / "frames"));
    EXPECT_FALSE(fs::exists(dir.path() / "frames.pvd"));
    EXPECT_FALSE(fs::exists(dir.path() / "frames.recycled" / "stale"));
    EXPECT_TRUE(fs::exists(dir.path() / "frames.recycled" / "frame_000001.vtm"));
  }
  EXPECT_FALSE(fs::exists(dir.path() / "frames.recycled"));
}

}  // namespace
}  // namespace mrsim
