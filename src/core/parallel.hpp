#pragma once
// Loops over fewer items than this run on one thread: for small meshes the fork/join of an
// OpenMP region costs more than the work, and with more threads than free cores a barrier can
// stall for a whole scheduler slice. Results never depend on it (every loop is a per-item
// gather), so tests may lower it to exercise the threaded path on small meshes.
namespace mrsim {
int parallel_threshold();
void set_parallel_threshold(int items);
}  // namespace mrsim
