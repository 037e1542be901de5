#include "time/explicit_updates.hpp"
#include "core/parallel.hpp"

namespace mrsim {

void kick(PointState& s, double dt) {
  const int n = s.size();
#pragma omp parallel for schedule(static) if (n >= parallel_threshold())
  for (int i = 0; i < n; ++i)
    if (s.free_point[i]) s.v[i] += (dt * s.inv_mass[i]) * s.f[i];
}

void drift(PointState& s, double dt) {
  const int n = s.size();
#pragma omp parallel for schedule(static) if (n >= parallel_threshold())
  for (int i = 0; i < n; ++i)
    if (s.free_point[i]) s.u[i] += dt * s.v[i];
}

}  // namespace mrsim
