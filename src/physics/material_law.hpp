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
  /// These scales with each of the seven components multiplied by `factors`' (all ones: these,
  /// bit for bit).
  StiffnessScales times(const std::array<double, 7>& factors) const;
};

/// object.calibration: per_tet: seven factors per tet on its level's tensor, in the order of
/// StiffnessScales::components() ({λ, xx, yy, zz, yz, xz, xy}): each tet its own orthotropic
/// tensor (docs/hierarchy.md "Per-tet tensors").
using TetTensors = std::vector<std::array<double, 7>>;

struct MaterialLaw {
  StrainMeasure strain = StrainMeasure::GreenLagrange;
  double lambda = 0, mu = 0;  // Pa
  double phi = 0, psi = 0;    // Pa.s
  double density = 1000;      // kg/m^3
  StiffnessScales scales;     // calibrated level; isotropic by default
  // object.calibration: per_tet: each tet's factors on the level's tensor (and damping), null:
  // all ones. The level's TetGeometry::scales carries each tet's product with `scales`.
  std::shared_ptr<const TetTensors> tet_tensors;

  bool damped() const { return phi != 0 || psi != 0; }
  /// P-wave speed √((λ+2μ)/ρ), the Courant speed of method.md §5.2 (largest scales, the
  /// stiffest tet's with tet_tensors).
  double p_wave_speed() const;
  /// λ, μ (or φ, ψ) bounding a tensor with scales `s` from above: λ·lambda, μ·max(mu); the
  /// level's own by default (one tet's: TetGeometry::scales_of()).
  double bound_lambda(const StiffnessScales& s) const { return lambda * s.lambda; }
  double bound_mu(const StiffnessScales& s) const { return mu * s.max_mu(); }
  double bound_phi(const StiffnessScales& s) const { return phi * s.lambda; }
  double bound_psi(const StiffnessScales& s) const { return psi * s.max_mu(); }
  double bound_lambda() const { return bound_lambda(scales); }
  double bound_mu() const { return bound_mu(scales); }
};

}  // namespace mrsim
