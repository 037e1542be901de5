#include "physics/level_model.hpp"

#include <algorithm>
#include <limits>

#include "physics/lumped_mass.hpp"

namespace mrsim {

namespace {

void edge_lengths(LevelModel& m) {
  const int n = m.num_points();
  m.mean_edge.assign(n, 0.0);
  m.min_edge.assign(n, std::numeric_limits<double>::infinity());
  for (int i = 0; i < n; ++i) {
    double sum = 0;
    for (int e = m.adj.nbr_start[i]; e < m.adj.nbr_start[i + 1]; ++e) {
      const double l = (m.mesh->points[m.adj.nbr[e]] - m.mesh->points[i]).norm();
      sum += l;
      m.min_edge[i] = std::min(m.min_edge[i], l);
    }
    m.mean_edge[i] = sum / std::max(1, m.adj.degree(i));
  }
}

// The level's spectra against its largest point bounds (physics/spectral_bound.hpp).
void measure_spectrum(LevelModel& m) {
  double k_max = 0, c_max = 0;
  for (const PointInertia& p : m.star)
    if (p.mass > 0) {
      k_max = std::max(k_max, p.stiffness / p.mass);
      c_max = std::max(c_max, p.damping / p.mass);
    }
  m.stiffness_spectrum =
      spectral_scale(largest_mass_scaled_eigenvalue(m.adj, m.K, m.mass), k_max);
  m.damping_spectrum = spectral_scale(largest_mass_scaled_eigenvalue(m.adj, m.D, m.mass), c_max);
}

}  // namespace

PointInertia calibrated(PointInertia p, const LevelModel& m) {
  p.stiffness *= m.stiffness_spectrum.scale;
  p.damping *= m.damping_spectrum.scale;
  return p;
}

LevelModel build_level_model(const TetMesh& mesh, const MaterialLaw& law) {
  LevelModel m;
  m.mesh = &mesh;
  m.law = law;
  m.geo = build_tet_geometry(mesh);
  m.adj = build_point_adjacency(static_cast<int>(mesh.points.size()), mesh.tets);
  m.mass = lumped_masses(m.geo, m.adj, law.density);
  m.lumped_volume = lumped_masses(m.geo, m.adj, 1.0);
  const EdgeOperators ops = build_edge_operators(m.geo, m.adj);
  m.K = combine_edge_operators(ops, law.lambda, law.mu);
  if (law.damped()) m.D = combine_edge_operators(ops, law.phi, law.psi);
  // B_ij = (∇N_j∇N_iᵀ + (∇N_i·∇N_j) I) V summed, so trace(B_ij) = 4 Σ V ∇N_i·∇N_j.
  m.laplacian_w.resize(ops.B.size());
  for (size_t e = 0; e < ops.B.size(); ++e) m.laplacian_w[e] = -ops.B[e].trace() / 4.0;
  edge_lengths(m);
  m.bounds = tet_energy_bounds(m.geo, law);
  m.star = star_inertia(m.adj, m.bounds, m.mass);
  measure_spectrum(m);
  return m;
}

}  // namespace mrsim
