#pragma once
// Clean interruption of a run (issue 18; docs/output.md "Interruption"): SIGINT (Ctrl-C) and
// SIGTERM (a cluster's time limit, `kill`) only raise a flag; the run finishes the frame under
// way, writes it and summary.json with status "interrupted", and exits 128 + the signal
// (130, 143). A second signal while it does so ends the process at once, as without mrsim.
namespace mrsim {

/// Installs the handlers (once; `mrsim run` only).
void watch_interruptions();

/// The signal received since watch_interruptions() (SIGINT, SIGTERM), or 0.
int interruption_signal();

}  // namespace mrsim
