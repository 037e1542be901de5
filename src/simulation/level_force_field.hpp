#pragma once
// Total force on the points of one level: internal (elastic + damping) + gravity m_i g.
#include "physics/internal_force.hpp"
#include "time/force_field.hpp"

namespace mrsim {

class LevelForceField final : public ForceField {
 public:
  LevelForceField(const LevelModel& model, const Vec3& gravity);
  void evaluate(const Vec3* u, const Vec3* v, Vec3* f) override;

 private:
  const LevelModel& model_;
  std::vector<Vec3> weight_;  // m_i g, precomputed
  ForceWorkspace ws_;
};

}  // namespace mrsim
