#include "time/explicit_updates.hpp"

#include "core/parallel.hpp"

namespace mrsim {

void kick(PointState& s, IndexSet points, double dt) { kick(s, s.f.data(), points, dt); }

void kick(PointState& s, const Vec3* force, IndexSet points, double dt) {
  parallel_for(points.count, [&](int k) {
    const int i = points[k];
    if (s.free_point[i]) s.v[i] += (dt * s.inv_mass[i]) * force[i];
  });
}

void save_forces(const PointState& s, IndexSet points, Vec3* saved) {
  parallel_for(points.count, [&](int k) { saved[points[k]] = s.f[points[k]]; });
}

void drift(PointState& s, IndexSet points, double dt) {
  parallel_for(points.count, [&](int k) {
    const int i = points[k];
    if (s.free_point[i]) s.u[i] += dt * s.v[i];
  });
}

void two_step_midpoint(PointState& s, IndexSet points, double dt, bool first) {
  parallel_for(points.count, [&](int k) {
    const int i = points[k];
    if (!s.free_point[i]) return;
    const Vec3 u = s.u[i], v = s.v[i];
    if (first) {
      s.v[i] += (dt * s.inv_mass[i]) * s.f[i];
      s.u[i] += dt * s.v[i];
    } else {
      s.v[i] = s.v_prev[i] + (2 * dt * s.inv_mass[i]) * s.f[i];
      s.u[i] = s.u_prev[i] + 2 * dt * v;
    }
    s.u_prev[i] = u;
    s.v_prev[i] = v;
  });
}

}  // namespace mrsim
