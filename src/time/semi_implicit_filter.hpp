#pragma once
// Semi-implicit step of thesis eq. (5.1) (method.md §5.3): after the explicit kick, each
// particle's velocity is multiplied by W_i = (I - dt²/m_i J_i)^-1, with J_i = ∂f_i/∂x_i probed
// once at rest by displacing particle i alone (amplitude 0.1 × the shortest edge of its mesh,
// one-sided differences, as in the source). J_i is exactly -K_ii for the Cauchy model.
// W_i is formed when applied (a 3×3 inverse, small next to the force): with time levels each
// particle has its own dt (method.md §5.3 "cache one W_i per time level" — not needed).
#include <vector>

#include "core/index_set.hpp"
#include "physics/level_model.hpp"
#include "time/point_state.hpp"

namespace mrsim {

/// J_i for every point of the level, probed at rest (u = v = 0).
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
