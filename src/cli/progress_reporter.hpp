#pragma once
// Progress on stderr (product.md): a bar with ETA redrawn in place when stderr is a terminal,
// otherwise one plain line about every 5 % of the frames. Silent with --quiet.
#include "simulation/run.hpp"

namespace mrsim {

class ProgressReporter {
 public:
  explicit ProgressReporter(bool enabled);
  void operator()(const RunProgress& p);
  void finish();

 private:
  bool enabled_, terminal_;
  int last_percent_ = -1;
  bool drawn_ = false;
};

}  // namespace mrsim
