#pragma once
// Error kinds map one-to-one onto the exit codes of product.md:
// InputError -> 2 (bad usage, scenario or mesh, reported before any simulation work),
// RunError   -> 1 (the simulation failed at run time: divergence, I/O during the run).
// `mrsim compare` uses 1 for "the runs differ" (kExitDiffer) and 2 for any input it cannot read.
#include <stdexcept>
#include <string>

namespace mrsim {

inline constexpr int kExitOk = 0;
inline constexpr int kExitRunFailure = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitDiffer = 1;  // mrsim compare: the runs differ beyond the tolerance

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct RunError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace mrsim
