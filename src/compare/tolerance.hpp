#pragma once
// The rule by which `mrsim compare` calls two floating-point values equal:
// |a - b| <= atol + rtol * max(|a|, |b|), NaN equals NaN (a run that produced NaN at the same
// place did the same thing), and an infinity equals only the same infinity. Integers never go
// through this rule: they are counters and compare exactly (array_diff.hpp).
#include <algorithm>
#include <cmath>

namespace mrsim {

struct Tolerance {
  double rtol = 0;  // relative, to the larger magnitude
  double atol = 0;  // absolute, in the unit of the values
};

inline bool within(double a, double b, const Tolerance& tolerance) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if (std::isinf(a) || std::isinf(b)) return a == b;
  const double scale = std::max(std::fabs(a), std::fabs(b));
  return std::fabs(a - b) <= tolerance.atol + tolerance.rtol * scale;
}

}  // namespace mrsim
