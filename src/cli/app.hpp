#pragma once
namespace mrsim {
/// The `mrsim` command line (product.md "Command line"); returns the process exit code.
int run_cli(int argc, char** argv);
}  // namespace mrsim
