#pragma once
// A block indented from above (validation.md §2.9): x, y in [-L, L], z in [-H, 0], bottom
// fixed, cells of width h0 under the tool (|x|, |y| < core) growing geometrically (ratio
// `growth`) towards the sides and the bottom. Linear (Cauchy) material, light damping.
#include <cmath>
#include <vector>

#include "mesh/box_mesh.hpp"
#include "simulation/hierarchical_simulation.hpp"
#include "simulation/stable_step.hpp"

namespace mrsim::testing {

struct IndentedBlock {
  double L = 0.02, H = 0.02;      // m
  double h0 = 4e-4, core = 2e-3;  // m: finest cell, half-width of the uniform core
  double growth = 1.35;
  double E = 1e4, nu = 0.3, density = 1000, psi = 0.02;

  double e_star() const { return E / (1 - nu * nu); }

  // Widths from the centre outwards over `half` metres: core cells, then growing ones.
  std::vector<double> half_widths(double half) const {
    std::vector<double> w;
    double x = 0;
    while (x + h0 <= core + 1e-12) { w.push_back(h0); x += h0; }
    double step = h0;
    while (x < half - 1e-12) {
      step = std::min(step * growth, half - x);
      if (half - x - step < 0.5 * step) step = half - x;  // no sliver at the end
      w.push_back(step);
      x += step;
    }
    return w;
  }

  TetMesh mesh() const {
    std::vector<double> side = half_widths(L);
    std::vector<double> across(side.rbegin(), side.rend());
    across.insert(across.end(), side.begin(), side.end());
    std::vector<double> depth = half_widths(H);  // from the surface down
    std::vector<double> z(depth.rbegin(), depth.rend());
    return make_graded_box_mesh(Vec3(-L, -L, -H), Vec3(L, L, 0), across, across, z);
  }

  HierarchySetup setup(const TetMesh& m, Tool tool) const {
    HierarchySetup s;
    s.law.strain = StrainMeasure::Cauchy;
    s.law.lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    s.law.mu = E / (2 * (1 + nu));
    s.law.density = density;
    s.law.psi = psi;
    s.fixed.resize(1);
    s.fixed[0].assign(m.points.size(), 0);
    for (size_t p = 0; p < m.points.size(); ++p)
      if (m.points[p].z() < -H + 1e-9) s.fixed[0][p] = 1;
    s.tools.push_back(std::move(tool));
    return s;
  }
};

/// Half the P-wave Courant estimate of the mesh (validation.md §2.7).
inline double courant_dt(const TetMesh& mesh, const MaterialLaw& law) {
  return 0.5 * shortest_edge(mesh) / std::sqrt((law.lambda + 2 * law.mu) / law.density);
}

/// A tool moving straight down from `start` to `end` (m, z of the tool frame's origin) over
/// [0, t_end] s, then holding.
inline Tool vertical_tool(ToolShape shape, double start, double end, double t_end,
                          double stiffness = 0) {
  Tool tool;
  tool.name = "tool";
  tool.shape = shape;
  tool.trajectory = ToolTrajectory({{0.0, Vec3(0, 0, start)}, {t_end, Vec3(0, 0, end)}},
                                   Interpolation::Linear, "test tool");
  tool.contact.stiffness = stiffness;
  return tool;
}

}  // namespace mrsim::testing
