#pragma once
// Semi-implicit step of thesis eq. (5.1) (method.md §5.3): after the explicit kick, each
// particle's velocity is multiplied by W_i = (I - dt²/m_i J_i)^-1, with J_i = ∂f_i/∂x_i at rest,
// particle i alone displaced. J_i = -K_ii, the rest tangent's diagonal block, for either strain
// measure (Green–Lagrange linearised at rest is the Cauchy model). The thesis probes J_i by a
// finite displacement (1/10 of the mesh's shortest edge, one-sided); with Green–Lagrange that
// adds a term of the probe over the tet's height, not symmetric, which left explicit more than
// the stable step counts (docs/integrators.md "The stable step": the filtered spectrum is that
// of K − 2 blockdiag K): at ν = 0.49 the bundled adaptive beam diverged at its computed step.
// W_i is formed when applied (a 3×3 inverse, small next to the force): with time levels each
// particle has its own dt (method.md §5.3 "cache one W_i per time level" — not needed).
#include <vector>

#include "core/index_set.hpp"
#include "physics/level_model.hpp"
#include "time/point_state.hpp"

namespace mrsim {

/// J_i = -K_ii for every point of the level (the level's edge matrices must be built: they are
/// for a semi-implicit level, physics/level_model.hpp edge_matrices_needed()).
std::vector<Mat3> point_jacobians(const LevelModel& model);

class SemiImplicitFilter {
 public:
  SemiImplicitFilter() = default;
  explicit SemiImplicitFilter(const LevelModel& model);
  /// v_i <- W_i v_i, W_i = (I - dt²/m_i J_i)^-1, for every free point of `points`.
  void apply(PointState& s, IndexSet points, double dt) const;
  bool empty() const { return jacobian_.empty(); }

 private:
  std::vector<Mat3> jacobian_;
};

}  // namespace mrsim
