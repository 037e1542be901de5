#pragma once
// Global mechanical quantities of one level, used for the log, the divergence guard and the
// conservation tests (validation.md §2.6). Fixed summation order: deterministic.
#include "physics/level_model.hpp"
#include "time/point_state.hpp"

namespace mrsim {

double kinetic_energy(const PointState& s, const std::vector<double>& mass);
/// Kinetic energy relative to the centre-of-mass velocity (excludes rigid translation).
double internal_kinetic_energy(const PointState& s, const std::vector<double>& mass);
Vec3 linear_momentum(const PointState& s, const std::vector<double>& mass);
/// Σ m_i (X_i + u_i) × v_i about the origin.
Vec3 angular_momentum(const PointState& s, const std::vector<double>& mass, const TetMesh& mesh);
Vec3 centre_of_mass(const TetMesh& mesh, const std::vector<double>& mass);
double max_displacement(const PointState& s);

}  // namespace mrsim
