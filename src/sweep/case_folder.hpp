#pragma once
// One case's folder DIR/case_NNNN: params.json, the run's outputs, stderr.txt and
// status.json, and the resume rule derived from what the folder holds.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "sweep/sweep_cases.hpp"

namespace mrsim::sweep {

/// How a case ended, as status.json records it.
struct CaseStatus {
  int exit_code = 0;
  std::string message;  // last stderr line(s) of a failure, "" on success
  double wall_time = 0;  // s, of the child process
};

enum class CaseState {
  pending,      // no folder: never started
  interrupted,  // no status.json (the sweep was killed while it ran), or the run stopped
                // cleanly on SIGINT/SIGTERM (exit 130/143: a time limit, a preemption)
  done,         // status.json with exit code 0
  failed,       // status.json with another exit code
};

std::filesystem::path case_folder(const std::filesystem::path& sweep_dir, int index);

/// Writes `content` to `path` through a temporary file and a rename, so readers (resume,
/// collect, a concurrent Slurm task) never see half a file. Throws RunError on failure.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

void write_params(const std::filesystem::path& folder, const SweepCase& c);
void write_status(const std::filesystem::path& folder, const CaseStatus& status);

/// status.json of the folder; nullopt when absent or unreadable (a torn file counts as absent).
std::optional<CaseStatus> read_status(const std::filesystem::path& folder);

CaseState case_state(const std::filesystem::path& folder);

/// Resume rule: finished cases are skipped, failed ones too unless `retry_failed`.
bool needs_run(CaseState state, bool retry_failed);

/// An interrupted case whose run left a checkpoint (docs/output.md): it goes on with
/// `mrsim run --resume` rather than from the start.
bool can_resume(const std::filesystem::path& folder);

/// Readies such a case to go on: only its status.json goes (it is running again).
void reopen_case_folder(const std::filesystem::path& folder);

/// Clears a folder (a left-over of an interrupted or retried run) and writes params.json.
void prepare_case_folder(const std::filesystem::path& folder, const SweepCase& c);

}  // namespace mrsim::sweep
