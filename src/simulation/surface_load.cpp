#include "simulation/surface_load.hpp"

#include <cmath>

namespace mrsim {

double load_factor(const std::vector<std::pair<double, double>>& profile, double t) {
  if (profile.empty()) return 1.0;
  if (t <= profile.front().first) return profile.front().second;
  for (std::size_t k = 1; k < profile.size(); ++k)
    if (t < profile[k].first) {
      const auto& [t0, f0] = profile[k - 1];
      const auto& [t1, f1] = profile[k];
      return f0 + (f1 - f0) * (t - t0) / (t1 - t0);
    }
  return profile.back().second;
}

double peak_load_factor(const std::vector<std::pair<double, double>>& profile, double t0,
                        double t1) {
  double peak = load_factor(profile, t0);
  auto consider = [&](double f) {
    if (std::abs(f) > std::abs(peak)) peak = f;
  };
  for (const auto& [t, f] : profile)
    if (t > t0 && t < t1) consider(f);
  consider(load_factor(profile, t1));
  return peak;
}

}  // namespace mrsim
