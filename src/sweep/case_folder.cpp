#include "sweep/case_folder.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

#include <unistd.h>

#include "core/error.hpp"

namespace mrsim::sweep {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path case_folder(const fs::path& sweep_dir, int index) {
  return sweep_dir / case_name(index);
}

void write_file_atomically(const fs::path& path, const std::string& content) {
  // The pid makes the temporary name unique: Slurm array tasks may write the same file at once.
  const fs::path temporary = path.string() + ".tmp." + std::to_string(getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << content;
    out.flush();
    if (!out) throw RunError("cannot write " + temporary.string());
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) throw RunError("cannot write " + path.string() + ": " + error.message());
}

void write_params(const fs::path& folder, const SweepCase& c) {
  // An ordered object keeps the parameters in the sweep's order for the reader.
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (const auto& [key, value] : c.params) params[key] = value;
  write_file_atomically(folder / "params.json", params.dump(2) + "\n");
}

void write_status(const fs::path& folder, const CaseStatus& status) {
  nlohmann::ordered_json j;
  j["exit_code"] = status.exit_code;
  j["message"] = status.message;
  j["wall_time"] = status.wall_time;
  write_file_atomically(folder / "status.json", j.dump(2) + "\n");
}

std::optional<CaseStatus> read_status(const fs::path& folder) {
  std::ifstream in(folder / "status.json", std::ios::binary);
  if (!in) return std::nullopt;
  const json j = json::parse(in, nullptr, false);
  if (!j.is_object() || !j.contains("exit_code") || !j["exit_code"].is_number_integer())
    return std::nullopt;
  CaseStatus status;
  status.exit_code = j["exit_code"].get<int>();
  status.message = j.value("message", std::string());
  status.wall_time = j.value("wall_time", 0.0);
  return status;
}

CaseState case_state(const fs::path& folder) {
  if (!fs::exists(folder)) return CaseState::pending;
  const auto status = read_status(folder);
  if (!status) return CaseState::interrupted;
  if (status->exit_code == 130 || status->exit_code == 143) return CaseState::interrupted;
  return status->exit_code == 0 ? CaseState::done : CaseState::failed;
}

bool can_resume(const fs::path& folder) {
  std::error_code error;
  return case_state(folder) == CaseState::interrupted &&
         fs::is_regular_file(folder / "checkpoint.h5", error) &&
         fs::is_regular_file(folder / "scenario.yaml", error) &&
         fs::is_regular_file(folder / "log.h5", error);
}

void reopen_case_folder(const fs::path& folder) {
  std::error_code error;
  fs::remove(folder / "status.json", error);
  if (error) throw RunError("cannot remove " + (folder / "status.json").string() + ": " +
                            error.message());
}

bool needs_run(CaseState state, bool retry_failed) {
  switch (state) {
    case CaseState::done:
      return false;
    case CaseState::failed:
      return retry_failed;
    case CaseState::pending:
    case CaseState::interrupted:
      return true;
  }
  return true;
}

void prepare_case_folder(const fs::path& folder, const SweepCase& c) {
  std::error_code error;
  fs::remove_all(folder, error);
  if (error) throw RunError("cannot clear " + folder.string() + ": " + error.message());
  fs::create_directories(folder, error);
  if (error) throw RunError("cannot create " + folder.string() + ": " + error.message());
  write_params(folder, c);
}

}  // namespace mrsim::sweep
