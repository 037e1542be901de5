#pragma once
// One mesh level with every point active: the single-level view used by validation tests.
// It is a one-level HierarchicalSimulation (no second copy of the setup), so what the tests
// validate is exactly what `mrsim run` integrates.
#include <cstdint>
#include <vector>

#include "simulation/hierarchical_simulation.hpp"

namespace mrsim {

struct LevelSetup {
  MaterialLaw law;
  Vec3 gravity = Vec3::Zero();
  Integrator integrator = Integrator::ModifiedEuler;
  double dt = 1e-3;                        // s, step
  std::vector<std::uint8_t> fixed;         // 1 = Dirichlet point; empty = none
  Vec3 initial_velocity = Vec3::Zero();    // m/s
  Vec3 initial_angular_velocity = Vec3::Zero();  // rad/s about the centre of mass
};

class LevelSimulation {
 public:
  LevelSimulation(const TetMesh& mesh, const LevelSetup& setup);
  /// Advances `steps` steps of the setup's dt.
  void advance(int steps) { sim_.advance(steps); }

  const LevelModel& model() const { return sim_.model(0); }
  const PointState& state() const { return sim_.state(0); }
  PointState& state() { return sim_.state(0); }
  double dt() const { return dt_; }
  std::int64_t force_evaluations() const { return sim_.force_evaluations(0); }
  double elastic_energy() const;

 private:
  static HierarchySetup one_level(const LevelSetup& setup);
  double dt_;
  HierarchicalSimulation sim_;
};

}  // namespace mrsim
