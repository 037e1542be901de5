#include "physics/material_law.hpp"

#include <algorithm>
#include <cmath>

namespace mrsim {

namespace {
// The strain component (i, j) of each fit value after λ: xx, yy, zz, yz, xz, xy.
constexpr int kComponent[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
}  // namespace

bool StiffnessScales::isotropic() const {
  return lambda == 1 && std::all_of(mu.begin(), mu.end(), [](double s) { return s == 1; });
}

double StiffnessScales::max_mu() const { return *std::max_element(mu.begin(), mu.end()); }

StiffnessScales StiffnessScales::from_components(const std::array<double, 7>& c) {
  StiffnessScales s;
  s.lambda = c[0];
  for (int k = 0; k < 6; ++k) {
    const auto [i, j] = kComponent[k];
    s.mu[3 * i + j] = s.mu[3 * j + i] = c[1 + k];
  }
  return s;
}

std::array<double, 7> StiffnessScales::components() const {
  std::array<double, 7> c{lambda};
  for (int k = 0; k < 6; ++k) c[1 + k] = mu[3 * kComponent[k][0] + kComponent[k][1]];
  return c;
}

StiffnessScales StiffnessScales::times(const std::array<double, 7>& factors) const {
  std::array<double, 7> c = components();
  for (int j = 0; j < 7; ++j) c[j] *= factors[j];
  return from_components(c);
}

double MaterialLaw::p_wave_speed() const {
  double modulus = bound_lambda() + 2 * bound_mu();
  if (tet_tensors)  // the stiffest tet's (object.calibration: per_tet)
    for (const auto& q : *tet_tensors) {
      const StiffnessScales s = scales.times(q);
      modulus = std::max(modulus, bound_lambda(s) + 2 * bound_mu(s));
    }
  return std::sqrt(modulus / density);
}

}  // namespace mrsim
