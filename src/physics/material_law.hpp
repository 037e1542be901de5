#pragma once
// Constitutive parameters as the force kernels see them (method.md §1): Lamé λ, μ for the
// elastic stress, φ, ψ for the strain-rate damping of thesis eq. 2.22, density for the masses.
namespace mrsim {

enum class StrainMeasure { Cauchy, GreenLagrange };

struct MaterialLaw {
  StrainMeasure strain = StrainMeasure::GreenLagrange;
  double lambda = 0, mu = 0;  // Pa
  double phi = 0, psi = 0;    // Pa.s
  double density = 1000;      // kg/m^3

  bool damped() const { return phi != 0 || psi != 0; }
  /// P-wave speed √((λ+2μ)/ρ), the Courant speed of method.md §5.2.
  double p_wave_speed() const;
};

}  // namespace mrsim
