#include "time/steps_per_frame.hpp"

#include <algorithm>
#include <cmath>

namespace mrsim {

long long fewest_steps(double frame_dt, double allowed, int parts, long long cap) {
  parts = std::max(parts, 1);
  const double needed = std::ceil(frame_dt / allowed);
  long long n = needed < static_cast<double>(cap) ? std::max(1LL, static_cast<long long>(needed))
                                                  : cap;
  // ceil() of a rounded quotient may be one off either way: the exact test is frame_dt / n.
  while (n > 1 && frame_dt / static_cast<double>(n - 1) <= allowed) --n;
  while (n < cap && frame_dt / static_cast<double>(n) > allowed) ++n;
  n = (n + parts - 1) / parts * parts;
  return std::min(n, cap / parts * parts);
}

}  // namespace mrsim
