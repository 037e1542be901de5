#include "physics/stable_step_bound.hpp"

#include <cmath>
#include <limits>

#include "core/symmetric_eigenvalues.hpp"

namespace mrsim {

namespace {

// |G|_F² and σ_max(G)² of a tet's shape-gradient matrix: what both of its bounds need.
struct GradientNorms {
  double frobenius2, largest2;
};

GradientNorms gradient_norms(const TetGradients& g) {
  Mat3 GGt = Mat3::Zero();
  for (const Vec3& ga : g) GGt.noalias() += ga * ga.transpose();
  return {GGt.trace(), symmetric_eigenvalues(GGt).maxCoeff()};
}

// V (p |G|_F² + 2 q σ_max(G)²): (p, q) = (λ, μ), or (φ, ψ) for damping.
double energy_bound(const GradientNorms& n, double V, double p, double q) {
  return V * (p * n.frobenius2 + 2 * q * n.largest2);
}

}  // namespace

TetEnergyBounds tet_energy_bounds(const TetGeometry& geo, const MaterialLaw& law) {
  const std::size_t n = geo.tets.size();
  TetEnergyBounds out;
  out.stiffness.resize(n);
  out.damping.assign(n, 0.0);
  for (std::size_t t = 0; t < n; ++t) {
    // One eigenvalue solve serves both bounds of the tet.
    const GradientNorms norms = gradient_norms(geo.grad[t]);
    // A calibrated tet's tensor is bounded by its largest scales (MaterialLaw::bound_*).
    const StiffnessScales& s = geo.scales_of(static_cast<int>(t), law.scales);
    out.stiffness[t] = energy_bound(norms, geo.volume[t], law.bound_lambda(s), law.bound_mu(s));
    if (law.damped())
      out.damping[t] = energy_bound(norms, geo.volume[t], law.bound_phi(s), law.bound_psi(s));
  }
  return out;
}

std::vector<PointInertia> star_inertia(const PointAdjacency& adj, const TetEnergyBounds& tets,
                                       const std::vector<double>& mass) {
  const int n = adj.num_points();
  std::vector<PointInertia> out(n);
  for (int i = 0; i < n; ++i) {
    PointInertia& p = out[i];
    p.mass = p.gravity_mass = mass[i];
    for (int s = adj.inc_start[i]; s < adj.inc_start[i + 1]; ++s) {
      p.stiffness += tets.stiffness[adj.inc_tet[s]];
      p.damping += tets.damping[adj.inc_tet[s]];
    }
  }
  return out;
}

double stable_step_of(const PointInertia& p, bool semi_implicit) {
  if (p.mass <= 0) return 0;
  const double share = semi_implicit ? kSemiImplicitShare : 1.0;
  const double w2 = (share * p.stiffness + p.contact_stiffness) / p.mass;
  const double gamma = p.damping / p.mass, disc = gamma * gamma + 4.0 * w2;
  const double denom = disc >= 0 ? gamma + std::sqrt(disc) : 0.0;
  return denom > 0 ? 4.0 / denom : std::numeric_limits<double>::infinity();
}

}  // namespace mrsim
