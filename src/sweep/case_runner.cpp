#include "sweep/case_runner.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>
#include <sstream>
#include <thread>

#include "core/error.hpp"
#include "core/text_file.hpp"

extern char** environ;

namespace mrsim::sweep {

namespace {

using Clock = std::chrono::steady_clock;

struct Running {
  const CaseJob* job;
  Clock::time_point start;
};

std::vector<char*> c_strings(std::vector<std::string>& strings) {
  std::vector<char*> pointers;
  for (auto& s : strings) pointers.push_back(s.data());
  pointers.push_back(nullptr);
  return pointers;
}

// stdin from /dev/null (a child must never eat the terminal's input), stdout discarded
// (`run --quiet` prints nothing useful there), stderr to the case's stderr.txt.
pid_t spawn_child(const RunnerOptions& options, const CaseJob& job) {
  std::vector<std::string> args = child_arguments(options, job);
  std::vector<std::string> env = child_environment();
  auto argv = c_strings(args);
  auto envp = c_strings(env);
  const std::string stderr_path = (job.folder / "stderr.txt").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, stderr_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0)
    throw RunError("cannot start " + args[0] + ": " + std::strerror(error));
  return pid;
}

CaseStatus status_of(int wait_status, const CaseJob& job, double wall_time) {
  CaseStatus status;
  status.wall_time = wall_time;
  const std::string tail = failure_message(read_text_if_any(job.folder / "stderr.txt"));
  if (WIFEXITED(wait_status)) {
    status.exit_code = WEXITSTATUS(wait_status);
    if (status.exit_code != 0) status.message = tail;
  } else {
    // Shell convention for a process ended by a signal: 128 + signal number.
    const int signal = WIFSIGNALED(wait_status) ? WTERMSIG(wait_status) : 0;
    status.exit_code = 128 + signal;
    status.message = "killed by signal " + std::to_string(signal) + " (" +
                     strsignal(signal) + ")" + (tail.empty() ? "" : ": " + tail);
  }
  return status;
}

// Blocks until one of our children ends; EINTR (e.g. SIGWINCH) is retried.
std::pair<pid_t, int> wait_any() {
  int wait_status = 0;
  pid_t pid = 0;
  do {
    pid = waitpid(-1, &wait_status, 0);
  } while (pid < 0 && errno == EINTR);
  if (pid < 0) throw RunError(std::string("waitpid failed: ") + std::strerror(errno));
  return {pid, wait_status};
}

}  // namespace

std::vector<std::string> child_arguments(const RunnerOptions& options, const CaseJob& job) {
  const std::string threads = std::to_string(std::max(1, options.threads));
  if (job.resume)
    return {options.executable.string(), "run", "--resume", job.folder.string(), "--quiet",
            "--threads", threads};
  std::vector<std::string> args{options.executable.string(), "run", options.base.string()};
  for (const auto& o : job.overrides) {
    args.push_back("--set");
    args.push_back(o);
  }
  args.insert(args.end(), {"-o", job.folder.string(), "--quiet", "--threads", threads});
  return args;
}

std::vector<std::string> child_environment() {
  std::vector<std::string> env;
  bool has_policy = false;
  for (char** e = environ; e && *e; ++e) {
    env.emplace_back(*e);
    has_policy = has_policy || env.back().rfind("OMP_WAIT_POLICY=", 0) == 0;
  }
  if (!has_policy) env.emplace_back("OMP_WAIT_POLICY=PASSIVE");
  return env;
}

std::string failure_message(const std::string& stderr_text) {
  std::vector<std::string> lines;
  std::istringstream in(stderr_text);
  for (std::string line; std::getline(in, line);)
    if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
  if (lines.empty()) return "";
  auto first = lines.end() - 1;
  for (auto it = lines.begin(); it != lines.end(); ++it)
    if (it->rfind("error: ", 0) == 0) first = it;
  std::string message;
  for (auto it = first; it != lines.end(); ++it) message += (message.empty() ? "" : "\n") + *it;
  if (message.rfind("error: ", 0) == 0) message.erase(0, 7);
  return message;
}

void run_cases(const std::vector<CaseJob>& jobs, const RunnerOptions& options,
               const std::function<void(const CaseJob&)>& on_start,
               const std::function<void(const CaseJob&, const CaseStatus&)>& on_finish) {
  std::map<pid_t, Running> running;
  std::size_t next = 0;
  while (next < jobs.size() || !running.empty()) {
    while (next < jobs.size() && static_cast<int>(running.size()) < std::max(1, options.jobs)) {
      const CaseJob& job = jobs[next++];
      running[spawn_child(options, job)] = {&job, Clock::now()};
      on_start(job);
    }
    const auto [pid, wait_status] = wait_any();
    const auto it = running.find(pid);
    if (it == running.end()) continue;  // not one of ours
    const Running done = it->second;
    running.erase(it);
    const double wall = std::chrono::duration<double>(Clock::now() - done.start).count();
    const CaseStatus status = status_of(wait_status, *done.job, wall);
    write_status(done.job->folder, status);
    on_finish(*done.job, status);
  }
}

int default_threads(int jobs) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, cores / std::max(1, jobs));
}

}  // namespace mrsim::sweep
