#pragma once
// Dynamic state of the points of one level, structure of arrays. `free_point[i]` is 0 for
// Dirichlet (fixed) points, whose u and v stay zero and are never integrated.
#include <cstdint>
#include <vector>

#include "core/vec.hpp"

namespace mrsim {

struct PointState {
  std::vector<Vec3> u, v, f;             // displacement (m), velocity (m/s), last total force (N)
  std::vector<double> inv_mass;          // 1/m_i, 1/kg
  std::vector<std::uint8_t> free_point;  // 1 if integrated, 0 if fixed
  // Störmer–Verlet only: the force of each point's last step, for its next first half-kick.
  // Kept apart from f because with time levels f is recomputed for other points in between.
  std::vector<Vec3> f_kick;
  // Newton–Cotes only: displacement and velocity one step back.
  std::vector<Vec3> u_prev, v_prev;

  void resize(int n) {
    u.assign(n, Vec3::Zero());
    v.assign(n, Vec3::Zero());
    f.assign(n, Vec3::Zero());
    inv_mass.assign(n, 0.0);
    free_point.assign(n, 1);
  }
  int size() const { return static_cast<int>(u.size()); }
};

}  // namespace mrsim
