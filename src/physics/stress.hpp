#pragma once
// Per-tet stresses of method.md §1–2.3, shared by the force kernels, the energy and the tests.
#include "core/vec.hpp"
#include "physics/material_law.hpp"

namespace mrsim {

/// Green–Lagrange strain E = ½(G + Gᵀ + GᵀG).
inline Mat3 green_strain(const Mat3& G) { return 0.5 * (G + G.transpose() + G.transpose() * G); }

/// Cauchy (linear) strain ε = ½(G + Gᵀ).
inline Mat3 cauchy_strain(const Mat3& G) { return 0.5 * (G + G.transpose()); }

/// Hooke law a·tr(E) I + 2b·E (λ, μ for stress; φ, ψ for eq. 2.22 damping), with a calibrated
/// level's orthotropic scales (MaterialLaw::scales): a·lambda, and b·mu[3i+j] on E_ij. The
/// isotropic law takes the plain expression (the same bits as before calibration existed).
inline Mat3 hooke(const Mat3& E, double a, double b, const StiffnessScales& s) {
  Mat3 S;
  if (s.isotropic()) {
    S = (2.0 * b) * E;
  } else {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) S(i, j) = (2.0 * (b * s.mu[3 * i + j])) * E(i, j);
  }
  S.diagonal().array() += (a * s.lambda) * E.trace();
  return S;
}

/// First Piola–Kirchhoff-like stress P = F (S + 𝒱) of §2.3 (Green), with the strain-rate
/// damping 𝒱 = φ tr(Ė) I + 2ψ Ė, Ė = ½(FᵀĠ + ĠᵀF). The nodal force is f_a = -V P ∇N_a.
/// `s`: the tet's scales (TetGeometry::scales_of()); the level's by default.
inline Mat3 green_piola(const Mat3& G, const Mat3* Gdot, const MaterialLaw& law,
                        const StiffnessScales& s) {
  const Mat3 F = Mat3::Identity() + G;
  Mat3 S = hooke(green_strain(G), law.lambda, law.mu, s);
  if (Gdot) {
    const Mat3 FtGd = F.transpose() * (*Gdot);
    S += hooke(0.5 * (FtGd + FtGd.transpose()), law.phi, law.psi, s);
  }
  return F * S;
}
inline Mat3 green_piola(const Mat3& G, const Mat3* Gdot, const MaterialLaw& law) {
  return green_piola(G, Gdot, law, law.scales);
}

/// Linear stress σ + ν (Cauchy): f_a = -V σ ∇N_a.
inline Mat3 cauchy_stress(const Mat3& G, const Mat3* Gdot, const MaterialLaw& law,
                          const StiffnessScales& s) {
  Mat3 sigma = hooke(cauchy_strain(G), law.lambda, law.mu, s);
  if (Gdot) sigma += hooke(cauchy_strain(*Gdot), law.phi, law.psi, s);
  return sigma;
}
inline Mat3 cauchy_stress(const Mat3& G, const Mat3* Gdot, const MaterialLaw& law) {
  return cauchy_stress(G, Gdot, law, law.scales);
}

/// Strain energy density (λ/2) tr(E)² + μ E:E of either strain (scaled per component on a
/// calibrated level or tet, `s`: ½ S:E with hooke()'s S).
inline double energy_density(const Mat3& E, const MaterialLaw& law, const StiffnessScales& s) {
  const double tr = E.trace();
  if (s.isotropic()) return 0.5 * law.lambda * tr * tr + law.mu * E.squaredNorm();
  double shear = 0;
  for (int k = 0; k < 9; ++k) shear += s.mu[k] * E.data()[k] * E.data()[k];
  return 0.5 * (law.lambda * s.lambda) * tr * tr + law.mu * shear;
}
inline double energy_density(const Mat3& E, const MaterialLaw& law) {
  return energy_density(E, law, law.scales);
}

}  // namespace mrsim
