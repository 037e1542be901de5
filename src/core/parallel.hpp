#pragma once
// Loops over fewer items than this run on one thread: for small meshes the fork/join of an
// OpenMP region costs more than the work, and with more threads than free cores a barrier can
// stall for a whole scheduler slice. Results never depend on it (every loop is a per-item
// gather), so tests may lower it to exercise the threaded path on small meshes.
#ifdef _OPENMP
#include <omp.h>
#endif

namespace mrsim {
int parallel_threshold();
void set_parallel_threshold(int items);

/// Whether a loop over n items opens an OpenMP region. A region that would run on one thread
/// is not opened at all: `#pragma omp parallel if(false)` still forks a serialized team and
/// costs a futex wake per call (16 % of a one-thread liver_probe run, issue 17).
inline bool use_threads(int n) {
#ifdef _OPENMP
  return n >= parallel_threshold() && omp_get_max_threads() > 1;
#else
  (void)n;
  return false;
#endif
}

/// body(k) for k in [0, n): a static OpenMP loop when use_threads(n), a plain loop otherwise.
/// Every body is a per-item gather, so the results are the same bit for bit either way.
template <class Body>
inline void parallel_for(int n, Body&& body) {
  if (!use_threads(n)) {
    for (int k = 0; k < n; ++k) body(k);
    return;
  }
#pragma omp parallel for schedule(static)
  for (int k = 0; k < n; ++k) body(k);
}

}  // namespace mrsim
