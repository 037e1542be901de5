#include "physics/tangent_growth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/symmetric_eigenvalues.hpp"

namespace mrsim {

namespace {

// The largest eigenvalue of E = ½(FᵀF − I) and tr E.
struct StrainTop {
  double e_max, trace;
};

Mat3 green_strain(const Mat3& grad_u) {
  const Mat3 F = Mat3::Identity() + grad_u;
  return 0.5 * (F.transpose() * F - Mat3::Identity());
}

StrainTop strain_top_of(const Mat3& E) {
  return {symmetric_eigenvalues(E)(2), E.trace()};
}

StrainTop strain_top(const Mat3& grad_u) { return strain_top_of(green_strain(grad_u)); }

// Gershgorin: every eigenvalue of E is below some E_ii + Σ_{j≠i} |E_ij|.
StrainTop strain_bound_of(const Mat3& E) {
  double top = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    top = std::max(top, E(i, i) + std::abs(E(i, (i + 1) % 3)) + std::abs(E(i, (i + 2) % 3)));
  return {top, E.trace()};
}

double growth_of(const StrainTop& e, const MaterialLaw& law, const StiffnessScales& s) {
  const double lambda = law.bound_lambda(s), mu = law.bound_mu(s);
  if (!(lambda + 2 * mu > 0)) return std::max(0.0, 2 * e.e_max);  // no stress: the material part
  const double stress = lambda * e.trace + 2 * mu * e.e_max;
  return std::max(0.0, 2 * e.e_max + std::max(0.0, stress) / (lambda + 2 * mu));
}

}  // namespace

double tangent_growth(const Mat3& grad_u, const MaterialLaw& law, const StiffnessScales& s) {
  return growth_of(strain_top(grad_u), law, s);
}

double damping_growth(const Mat3& grad_u) { return std::max(0.0, 2 * strain_top(grad_u).e_max); }

double largest_tangent_growth(const TetGeometry& geo, std::span<const int> tets,
                              const std::vector<Vec3>& u, const MaterialLaw& law) {
  double top = 0;
  for (const int t : tets)
    top = std::max(top, tangent_growth(tet_gradient(geo.grad[t], geo.tets[t], u.data()), law,
                                       geo.scales_of(t, law.scales)));
  return top;
}

double tangent_growths_of(const TetGeometry& geo, std::span<const int> tets,
                          const std::vector<Vec3>& u, const MaterialLaw& law,
                          std::vector<double>& stiffness, std::vector<double>& damping,
                          GrowthsNeeded needed) {
  for (const int t : tets)
    for (const int a : geo.tets[t]) stiffness[a] = damping[a] = 0.0;
  double top = 0;
  for (std::size_t k = 0; k < tets.size(); ++k) {
    if (k + kTetPrefetchAhead < tets.size()) prefetch_tet(geo, tets[k + kTetPrefetchAhead]);
    const int t = tets[k];
    const Mat3 E = green_strain(tet_gradient(geo.grad[t], geo.tets[t], u.data()));
    const StiffnessScales& scales = geo.scales_of(t, law.scales);
    // g and g_d grow with e_max: a bound on it bounds both, and below the thresholds suffices.
    StrainTop e = strain_bound_of(E);
    if (growth_of(e, law, scales) > needed.stiffness_above || 2 * e.e_max > needed.damping_above)
      e = strain_top_of(E);
    const double g = growth_of(e, law, scales);
    top = std::max(top, g);
    const double g_d = std::max(0.0, 2 * e.e_max);
    for (const int a : geo.tets[t]) {
      stiffness[a] = std::max(stiffness[a], g);
      damping[a] = std::max(damping[a], g_d);
    }
  }
  return top;
}

}  // namespace mrsim
