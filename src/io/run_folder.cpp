#include "io/run_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <string>
#include <string_view>
#include <system_error>

#include "core/error.hpp"
#include "io/file_recycler.hpp"

namespace mrsim {

namespace {

namespace fs = std::filesystem;

// What a run writes into its folder (docs/output.md "Layout").
// frames.recycled first: a run killed before it ended leaves one, which goes before frames/ takes
// its name.
constexpr const char* kRecycled = kRecycledFramesDir;
constexpr std::array<const char*, 9> kOutputs = {
    kRecycled,      "frames",        "frames.pvd",       "frames.pvd.spare", "log.h5",
    "summary.json", "scenario.yaml", "checkpoint.h5",    "checkpoint.h5.tmp"};

std::string holder_of(int fd) {
  std::array<char, 32> pid{};
  const ssize_t n = pread(fd, pid.data(), pid.size() - 1, 0);
  return n > 0 ? " (pid " + std::string(pid.data(), static_cast<std::size_t>(n)) + ")" : "";
}

fs::path normal(const fs::path& p) {
  std::error_code ec;
  return fs::weakly_canonical(p, ec);
}

// `inside` is `outer` or below it (both absolute and normal: normal()).
bool is_within(const fs::path& inside, const fs::path& outer) {
  const auto [end, _] = std::mismatch(outer.begin(), outer.end(), inside.begin(), inside.end());
  return end == outer.end();
}

void clear_previous_run(const fs::path& dir, const std::vector<fs::path>& inputs) {
  std::vector<fs::path> normal_inputs;  // each resolved once, not once per output it is held to
  for (const char* name : kOutputs) {
    std::error_code ec;
    if (!fs::exists(dir / name, ec)) continue;
    if (normal_inputs.empty())
      for (const fs::path& input : inputs)
        normal_inputs.push_back(input.empty() ? input : normal(input));
    const fs::path output = normal(dir / name);
    for (std::size_t k = 0; k < inputs.size(); ++k)
      if (!inputs[k].empty() && is_within(normal_inputs[k], output))
        throw InputError("the output folder " + dir.string() + " holds an input of this run, " +
                         inputs[k].string() + ", where the run writes " + name +
                         "; choose another output folder (-o)");
    // The old frames are not removed but kept for the new ones' files (io/file_recycler.hpp);
    // what the new run does not reuse goes when it ends.
    if (std::string_view(name) == "frames") fs::rename(dir / name, dir / kRecycled, ec);
    if (std::string_view(name) != "frames" || ec) fs::remove_all(dir / name, ec);
    if (ec)
      throw RunError("cannot remove the previous run's " + (dir / name).string() + ": " +
                     ec.message());
  }
}

}  // namespace

RunFolder::RunFolder(const fs::path& dir, const std::vector<fs::path>& inputs, Mode mode)
    : dir_(dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw RunError("cannot create " + dir.string() + ": " + ec.message());
  const fs::path lock = dir / kLockFile;
  fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw RunError("cannot open " + lock.string() + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    const std::string who = holder_of(fd_);
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK)
      throw InputError(dir.string() + " is the output folder of a run still going" + who +
                       "; choose another folder (-o) or wait for it to finish");
    throw RunError("cannot lock " + lock.string() + ": " + std::strerror(error));
  }
  const std::string pid = std::to_string(::getpid());
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
    // The pid is only a courtesy for the message above; the lock is what counts.
  }
  try {
    if (mode == Mode::Resume) {
      // The run goes on: its outputs stay; summary.json is written again when it ends.
      fs::remove(dir / "summary.json", ec);
      fs::remove(dir / "checkpoint.h5.tmp", ec);
    } else {
      clear_previous_run(dir, inputs);
    }
  } catch (...) {
    ::close(fd_);
    fd_ = -1;
    throw;
  }
}

void RunFolder::remember(const std::string& name) {
  struct stat st {};
  if (::stat((dir_ / name).c_str(), &st) != 0)
    throw RunError("cannot find " + (dir_ / name).string() + ": " + std::strerror(errno));
  remembered_.push_back({name, st.st_dev, st.st_ino});
}

void RunFolder::check_intact() const {
  struct stat lock {};
  if (::fstat(fd_, &lock) != 0 || lock.st_nlink == 0)
    throw RunError("the output folder " + dir_.string() +
                   " was removed during the run: its outputs are lost; the run stops");
  for (const Identity& file : remembered_) {
    struct stat st {};
    if (::stat((dir_ / file.name).c_str(), &st) != 0 || st.st_dev != file.device ||
        st.st_ino != file.inode)
      throw RunError((dir_ / file.name).string() +
                     " was removed or replaced during the run: what the run writes to it is "
                     "lost; the run stops");
  }
}

RunFolder::~RunFolder() {
  std::error_code ignored;  // the previous run's frame files the run did not reuse
  if (fd_ >= 0) fs::remove_all(dir_ / kRecycled, ignored);
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

}  // namespace mrsim
