#pragma once
// The exit codes of every mrsim command (product.md "Exit codes"): what a command throws becomes
// its code and one "error: ..." line on stderr.
#include <functional>

namespace mrsim {

/// Runs `command`: InputError -> 2, RunError, out of memory or any other exception -> 1.
int guarded_run(const std::function<int()>& command);

}  // namespace mrsim
