#pragma once
// `mrsim compare RUN_A RUN_B [--rtol R] [--atol A]`: golden-file regression between two output
// folders of `mrsim run` (issue 7; docs/output.md "Comparing runs").
#include <CLI/CLI.hpp>
#include <functional>

namespace mrsim {

struct CompareCommand {
  CLI::App* command = nullptr;  // true (parsed) when the user chose `compare`
  // Prints the report on stdout and returns kExitOk or kExitDiffer; every failure to read
  // the inputs propagates as InputError (exit 2, never 1, which means "differ").
  std::function<int()> run;
};

/// Registers the subcommand and its options on `app`.
CompareCommand add_compare_command(CLI::App& app);

}  // namespace mrsim
