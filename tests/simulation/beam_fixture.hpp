#pragma once
// The cantilever of validation.md §2: 0.1 x 0.02 x 0.02 m, E = 1e6 Pa, ν = 0.3, ρ = 1000,
// face x = 0 clamped, gravity -z. Structured Kuhn meshes n x n/5 x n/5.
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/box_mesh.hpp"
#include "mesh/mesh_reader.hpp"
#include "simulation/level_simulation.hpp"

namespace mrsim::testing {

inline constexpr double kBeamL = 0.1, kBeamH = 0.02;
inline constexpr double kE = 1.0e6, kNu = 0.3;

inline TetMesh beam_mesh(int nx) {
  return make_box_mesh(Vec3(0, 0, 0), Vec3(kBeamL, kBeamH, kBeamH), nx, nx / 5, nx / 5);
}

/// Level k of the bundled three-level beam (scenarios/meshes/beam_L<k>.vtu, gmsh, metres).
inline TetMesh bundled_beam_level(int level) {
  return read_tet_mesh(std::filesystem::path(MRSIM_SOURCE_DIR) / "scenarios" / "meshes" /
                           ("beam_L" + std::to_string(level) + ".vtu"),
                       LengthUnit::Metre);
}

inline LevelSetup beam_setup(const TetMesh& mesh, Integrator integ, double dt,
                             StrainMeasure strain = StrainMeasure::Cauchy) {
  LevelSetup s;
  s.law.strain = strain;
  s.law.lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));
  s.law.mu = kE / (2 * (1 + kNu));
  s.law.density = 1000;
  s.gravity = Vec3(0, 0, -9.81);
  s.integrator = integ;
  s.dt = dt;
  s.fixed.assign(mesh.points.size(), 0);
  for (size_t i = 0; i < mesh.points.size(); ++i) s.fixed[i] = mesh.points[i].x() < 1e-12;
  return s;
}

/// Mean uz over the nodes of the tip face x = L (m; negative when the beam sags).
inline double tip_uz(const PointState& state, const TetMesh& mesh) {
  double sum = 0;
  int n = 0;
  for (size_t i = 0; i < mesh.points.size(); ++i)
    if (mesh.points[i].x() > kBeamL - 1e-9) {
      sum += state.u[i].z();
      ++n;
    }
  return sum / n;
}

inline double tip_deflection(const LevelSimulation& sim, const TetMesh& mesh) {
  return tip_uz(sim.state(), mesh);
}

/// Mean value and frequency of an oscillating signal sampled every dt, measured over the
/// longest span of whole periods (between the first and last upward mean crossings).
struct Oscillation {
  double mean = 0, frequency = 0;
  int periods = 0;
};

inline Oscillation measure_oscillation(const std::vector<double>& w, double dt) {
  Oscillation o;
  double mean = 0;
  for (double x : w) mean += x;
  mean /= static_cast<double>(w.size());
  for (int iter = 0; iter < 3; ++iter) {
    std::vector<double> up;  // upward crossing times, linearly interpolated
    for (size_t k = 1; k < w.size(); ++k)
      if (w[k - 1] < mean && w[k] >= mean)
        up.push_back(dt * (static_cast<double>(k - 1) + (mean - w[k - 1]) / (w[k] - w[k - 1])));
    if (up.size() < 2) return o;
    o.periods = static_cast<int>(up.size()) - 1;
    o.frequency = o.periods / (up.back() - up.front());
    const size_t a = static_cast<size_t>(up.front() / dt), b = static_cast<size_t>(up.back() / dt);
    double s = 0;
    for (size_t k = a; k < b; ++k) s += w[k];
    mean = s / static_cast<double>(b - a);
  }
  o.mean = mean;
  return o;
}

}  // namespace mrsim::testing
