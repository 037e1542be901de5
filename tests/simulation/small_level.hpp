#pragma once
// A small level and a damped Green–Lagrange law, for the tests of what a run keeps between runs
// (simulation/spectrum_cache.hpp, simulation/level_array_cache.hpp).
#include "mesh/box_mesh.hpp"
#include "physics/material_law.hpp"

namespace mrsim::test {

inline TetMesh small_box() {
  return make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.03, 0.02), 5, 2, 2);
}

inline MaterialLaw damped_law() {
  MaterialLaw l;
  l.lambda = 4.0e4;
  l.mu = 1.0e4;
  l.psi = 5;
  return l;
}

}  // namespace mrsim::test
