#pragma once
// Constitutive parameters as the force kernels see them (method.md §1): Lamé λ, μ for the
// elastic stress, φ, ψ for the strain-rate damping of thesis eq. 2.22, density for the masses.
#include <array>
#include <memory>
#include <vector>

namespace mrsim {

enum class StrainMeasure { Cauchy, GreenLagrange };

/// A calibrated coarse level's orthotropic tensor (hierarchy/level_calibration.hpp,
/// docs/hierarchy.md "Calibrated levels"): the stress is
///   S_ij = (λ·lambda) tr(E) δ_ij + 2 (μ·mu[3i + j]) E_ij      (mu symmetric),
/// and the damping takes the same scales (φ like λ, ψ like μ), so that the level's damping stays
/// proportional to its stiffness. All ones (the default) is the isotropic law, bit for bit.
struct StiffnessScales {
  double lambda = 1;
  std::array<double, 9> mu = {1, 1, 1, 1, 1, 1, 1, 1, 1};

  bool isotropic() const;
  double max_mu() const;
  /// From the fit's seven values {λ, xx, yy, zz, yz, xz, xy}.
  static StiffnessScales from_components(const std::array<double, 7>& c);
  std::array<double, 7> components() const;
};

struct MaterialLaw {
  StrainMeasure strain = StrainMeasure::GreenLagrange;
  double lambda = 0, mu = 0;  // Pa
  double phi = 0, psi = 0;    // Pa.s
  double density = 1000;      // kg/m^3
  StiffnessScales scales;     // calibrated level; isotropic by default
  // object.calibration: per_tet: one more factor per tet of the level on its whole tensor (and
  // damping); null: 1 for every tet. The level's TetGeometry::elastic_volume carries it.
  std::shared_ptr<const std::vector<double>> tet_scales;

  bool damped() const { return phi != 0 || psi != 0; }
  /// P-wave speed √((λ+2μ)/ρ), the Courant speed of method.md §5.2 (largest scales).
  double p_wave_speed() const;
  /// λ, μ (or φ, ψ) bounding the calibrated tensor from above: λ·lambda, μ·max(mu).
  double bound_lambda() const { return lambda * scales.lambda; }
  double bound_mu() const { return mu * scales.max_mu(); }
  double bound_phi() const { return phi * scales.lambda; }
  double bound_psi() const { return psi * scales.max_mu(); }
};

}  // namespace mrsim
