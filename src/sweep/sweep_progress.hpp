#pragma once
// "sweep: 3/12 done, 1 failed, 2 running, ETA 1m20s" on stderr: rewritten in place on a
// terminal, one line per finished case otherwise (logs of batch jobs stay readable).
#include <chrono>
#include <string>

namespace mrsim::sweep {

class SweepProgress {
 public:
  /// `total` cases in the sweep, `already_done` / `already_failed` of them finished before.
  SweepProgress(int total, int already_done, int already_failed, int jobs, bool enabled);
  void started();
  void finished(bool ok);
  /// Ends the in-place line on a terminal.
  void close();
  /// The status line (without newline), for tests and logs.
  std::string line() const;

 private:
  void print();
  int total_, done_, failed_, running_ = 0, jobs_;
  int finished_here_ = 0;  // cases finished by this process: the ETA's sample
  bool enabled_, terminal_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// "45s", "1m20s", "2h05m".
std::string format_duration(double seconds);

}  // namespace mrsim::sweep
