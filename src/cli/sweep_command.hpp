#pragma once
// `mrsim sweep SWEEP.yaml [-j N] [-o DIR] [--threads T] [--retry-failed] [--quiet]
// [--collect | --case K]`: cases of a base scenario run locally (issue 8; docs/sweeps.md).
#include <CLI/CLI.hpp>
#include <functional>

namespace mrsim {

struct SweepCommand {
  CLI::App* command = nullptr;  // true (parsed) when the user chose `sweep`
  // Returns 0 (every case done) or 1 (some failed); a bad sweep is an InputError (exit 2).
  std::function<int()> run;
};

/// Registers the subcommand and its options on `app`.
SweepCommand add_sweep_command(CLI::App& app);

}  // namespace mrsim
