#pragma once
// Signal measurements shared by the dynamic validation checks (validation.md §2.4, §2.8):
// extrema of an oscillation about a known level, the logarithmic decrement, arrival times.
// Signals are sampled every dt from t = 0 (sample k at time k dt).
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace mrsim::testing {

/// One extremum of a signal: time (s) and deviation from the reference level.
struct Extremum {
  double t = 0, value = 0;
};

/// The largest deviation of each lobe of `w` above `level` (the signal between an upward and
/// the next downward crossing of `level`), refined by a parabola through the three samples
/// around it. One extremum per cycle whatever ripple higher modes put on the lobe.
inline std::vector<Extremum> lobe_maxima(const std::vector<double>& w, double dt, double level) {
  std::vector<Extremum> out;
  std::size_t k = 1;
  while (k < w.size()) {
    while (k < w.size() && !(w[k - 1] < level && w[k] >= level)) ++k;  // upward crossing
    std::size_t best = k;
    for (; k < w.size() && w[k] >= level; ++k)
      if (w[k] > w[best]) best = k;
    if (k >= w.size()) break;  // lobe cut by the end of the record: not a full one
    double t = dt * static_cast<double>(best), v = w[best] - level;
    if (best > 0 && best + 1 < w.size()) {
      const double a = w[best - 1], b = w[best], c = w[best + 1];
      const double curv = a - 2 * b + c;
      if (curv < 0) {
        const double s = 0.5 * (a - c) / curv;  // vertex offset, in samples, within ±1/2
        t += s * dt;
        v = b - 0.25 * (a - c) * s - level;
      }
    }
    out.push_back({t, v});
  }
  return out;
}

/// Mean logarithmic decrement δ = ln(a_k / a_{k+1}) over the lobes first..last (inclusive):
/// ln(a_first / a_last) / (last - first).
inline double log_decrement(const std::vector<Extremum>& peaks, std::size_t first,
                            std::size_t last) {
  return std::log(peaks[first].value / peaks[last].value) / static_cast<double>(last - first);
}

/// Damping ratio from the logarithmic decrement: ζ = δ / √(4π² + δ²) (validation.md §2.8).
inline double damping_ratio(double delta) {
  return delta / std::sqrt(4 * std::numbers::pi * std::numbers::pi + delta * delta);
}

/// First time the signal reaches `threshold` (>= 0) from below, linearly interpolated
/// between samples; negative if it never does.
inline double arrival_time(const std::vector<double>& s, double dt, double threshold) {
  for (std::size_t k = 1; k < s.size(); ++k)
    if (s[k - 1] < threshold && s[k] >= threshold)
      return dt * (static_cast<double>(k - 1) + (threshold - s[k - 1]) / (s[k] - s[k - 1]));
  return -1;
}

/// Largest sample of a signal.
inline double peak_value(const std::vector<double>& s) {
  double m = s.empty() ? 0 : s.front();
  for (double x : s) m = x > m ? x : m;
  return m;
}

/// (max - min) / mean of a few values: the spread of one quantity across levels.
inline double relative_spread(const std::vector<double>& x) {
  double lo = x.front(), hi = x.front(), sum = 0;
  for (double v : x) {
    lo = v < lo ? v : lo;
    hi = v > hi ? v : hi;
    sum += v;
  }
  return (hi - lo) / (sum / static_cast<double>(x.size()));
}

}  // namespace mrsim::testing
