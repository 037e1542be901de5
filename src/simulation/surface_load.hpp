#pragma once
// A surface load as the dynamics sees it (scenario `loads`): nodal forces on the finest level's
// skin at factor 1, scaled in time by a piecewise-linear profile. Each nodal force reaches the
// points that simulate its point with the interpolation weights that move it (the transpose of
// the ghost/inactive interpolation), so the total force is exact whatever level is active and
// its virtual work matches the displayed displacement.
#include <utility>
#include <vector>

#include "core/vec.hpp"

namespace mrsim {

/// Nodal forces of one load on one level at factor 1; they sum to the load's force.
struct NodalLoad {
  std::vector<int> points;
  std::vector<Vec3> force;  // N
};

struct SurfaceLoad {
  NodalLoad finest;                                // on the finest level
  std::vector<std::pair<double, double>> profile;  // (time s, factor), increasing times
};

/// Piecewise-linear profile, constant beyond its ends; 1 when empty.
double load_factor(const std::vector<std::pair<double, double>>& profile, double t);

/// The factor of largest magnitude the profile takes over [t0, t1] (at an end or at a knot
/// within: the profile is linear between its knots), the earliest of equal magnitudes.
double peak_load_factor(const std::vector<std::pair<double, double>>& profile, double t0,
                        double t1);

}  // namespace mrsim
