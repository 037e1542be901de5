#include "core/symmetric_eigenvalues.hpp"

#include <algorithm>
#include <cmath>

#include "core/portable_math.hpp"

namespace mrsim {

namespace {

// Roots of det(B - x I) = 0 for a symmetric B with zero trace and entries in [-1, 1]:
// x^3 - c x - d = 0 with c = -(sum of the principal 2x2 minors), d = det B. With x = 2 rho cos t,
// rho = sqrt(c / 3): cos 3t = d / (2 rho^3), three real roots.
Vec3 trace_free_roots(const Mat3& b) {
  const double b00 = b(0, 0), b11 = b(1, 1), b22 = b(2, 2);
  const double b10 = b(1, 0), b20 = b(2, 0), b21 = b(2, 1);
  const double minors = b00 * b11 - b10 * b10 + b00 * b22 - b20 * b20 + b11 * b22 - b21 * b21;
  const double det = b00 * (b11 * b22 - b21 * b21) - b10 * (b10 * b22 - b21 * b20) +
                     b20 * (b10 * b21 - b11 * b20);
  const double c_third = std::max(0.0, -minors / 3.0);
  const double half_det = 0.5 * det;
  // rho^6 - (d/2)^2 = (rho^3 sin 3t)^2 >= 0 for a symmetric matrix; rounding may make it
  // slightly negative.
  const double sin_part = std::max(0.0, c_third * c_third * c_third - half_det * half_det);
  const double rho = std::sqrt(c_third);
  const double t = portable::atan2(std::sqrt(sin_part), half_det) / 3.0;
  const double cos_t = portable::cos(t), sin_t = portable::sin(t);
  constexpr double kSqrt3 = 1.7320508075688772;
  Vec3 roots(-rho * (cos_t + kSqrt3 * sin_t), -rho * (cos_t - kSqrt3 * sin_t), 2.0 * rho * cos_t);
  std::sort(roots.data(), roots.data() + 3);
  return roots;
}

}  // namespace

Vec3 symmetric_eigenvalues(const Mat3& m) {
  Mat3 b = m.selfadjointView<Eigen::Lower>();
  const double shift = b.trace() / 3.0;
  b.diagonal().array() -= shift;
  const double scale = b.cwiseAbs().maxCoeff();
  if (scale != scale) return Vec3::Constant(scale);  // NaN in, NaN out
  if (scale == 0) return Vec3::Constant(shift);     // a multiple of the identity
  b /= scale;
  return (trace_free_roots(b) * scale).array() + shift;
}

}  // namespace mrsim
