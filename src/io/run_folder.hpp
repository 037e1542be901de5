#pragma once
// One run per output folder (issue 18; docs/output.md "One run per folder"). The folder is
// locked (flock on OUTDIR/.mrsim.lock) before anything is written: a second run into a folder
// whose run is still going exits 2 and touches nothing. A folder that holds a finished run is
// taken over cleanly: the outputs mrsim writes there (frames.pvd, log.h5, summary.json,
// scenario.yaml, checkpoint.h5) are removed first, and frames/ becomes frames.recycled/, whose
// files the new frames are written over (io/file_recycler.hpp) and whose rest is removed when the
// run ends, so that no stale frame of the old run stays beside the new ones. Other files of the folder are left alone, and so is any input of the run
// (`mrsim run scenario.yaml -o .` must not delete its own scenario.yaml: that is refused). The
// lock is released when the process ends, however it ends (the kernel drops it), so a killed
// run never blocks the next.
#include <filesystem>
#include <string>
#include <vector>

namespace mrsim {

class RunFolder {
 public:
  /// Creates `dir` if needed, locks it, then removes the previous run's outputs. Throws
  /// InputError when another process holds the lock or when an output to remove is (or holds)
  /// one of `inputs`, RunError when the folder cannot be made or cleared.
  /// Resume (mrsim run --resume): the folder must exist; its outputs stay (the run goes on
  /// with them), only summary.json goes, written again when the run ends.
  enum class Mode { Fresh, Resume };
  RunFolder(const std::filesystem::path& dir, const std::vector<std::filesystem::path>& inputs,
            Mode mode = Mode::Fresh);
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  /// Remember `name` (a file of the folder the run keeps open, log.h5) as it is now.
  void remember(const std::string& name);
  /// Throws RunError when the folder, its lock or a remembered file was removed or replaced
  /// since (issue 18 defect 5: a removed folder went unnoticed, exit 0, its log lost).
  void check_intact() const;

  /// Name of the lock file inside the folder (kept: removing it would let two runs lock two
  /// different files).
  static constexpr const char* kLockFile = ".mrsim.lock";

 private:
  struct Identity {
    std::string name;
    unsigned long long device = 0, inode = 0;
  };
  std::filesystem::path dir_;
  int fd_ = -1;
  std::vector<Identity> remembered_;
};

}  // namespace mrsim
