#pragma once
// One step of the chosen scheme (method.md §5.1, §5.3) for one or several blocks of points (the
// levels of the hierarchy). Every force of a step is computed before any point moves
// (method.md §5.4: "all forces first, then integrate"), so the result does not depend on the
// order of the blocks; `sync` runs after every position update (the ghost refresh, §4.8) and
// `gathered` after every force evaluation of all blocks (the ghost force transfer).
// Exactly one force evaluation per point per step for every scheme.
// Time levels (method.md §5.2, §5.4): a block integrates with dt × dt_scale, and several blocks
// may integrate points of one state with one force field: only the block that names the field
// evaluates it.
#include <cstdint>
#include <functional>
#include <vector>

#include "core/index_set.hpp"
#include "core/task_clock.hpp"
#include "time/force_field.hpp"
#include "time/integrator_kind.hpp"
#include "time/momentum_restoration.hpp"
#include "time/point_state.hpp"
#include "time/semi_implicit_filter.hpp"

namespace mrsim {

struct IntegrationBlock {
  PointState* state = nullptr;
  ForceField* forces = nullptr;              // nullptr: another block evaluates this state
  const std::vector<int>* points = nullptr;  // integrated points; nullptr = all of state
  const SemiImplicitFilter* filter = nullptr;  // semi-implicit only
  const Vec3* rest = nullptr;                // rest positions (momentum restoration only)
  double dt_scale = 1.0;                     // this block's step is dt × dt_scale
};

class Stepper {
 public:
  Stepper(Integrator kind, std::vector<IntegrationBlock> blocks, std::function<void()> sync = {},
          std::function<void()> gathered = {});

  /// Must be called once before the first step (Störmer–Verlet needs f at t = 0), and again
  /// after the point sets changed (a split or merge) for the same reason. Newton–Cotes then
  /// takes one modified-Euler step to have a step before (and again when dt changes).
  void start();
  void step(double dt);
  /// The first half of a modified-Euler / semi-implicit step: every force evaluated, every
  /// block's points kicked (v += f dt × dt_scale / m, then the semi-implicit filter and the
  /// momentum restoration). Positions do not move. The multirate scheme of time levels drifts
  /// positions itself (method.md §5.4, time/w_cycle.hpp).
  void kick_step(double dt);
  std::int64_t force_evaluations(int block) const { return evaluations_[block]; }
  /// What a checkpoint keeps of the stepper: the evaluation counters and Newton–Cotes' step
  /// before (0: none). The saved forces and previous states live in the PointStates.
  const std::vector<std::int64_t>& evaluations() const { return evaluations_; }
  double previous_dt() const { return previous_dt_; }
  /// Takes them back (after start(), which forgets the step before). Throws
  /// std::invalid_argument when the counters are not one per block.
  void restore(std::vector<std::int64_t> evaluations, double previous_dt);
  Integrator kind() const { return kind_; }
  /// semi_implicit_momentum when the blocks hold only part of the body (time levels): the
  /// momentum the filter takes from them is given back over the whole `body` (state, points,
  /// rest of each block).
  void restore_momentum_over(std::vector<IntegrationBlock> body);
  /// The blocks, whose point lists and dt_scale may be changed between steps.
  IntegrationBlock& block(int k) { return blocks_[k]; }
  /// Times every force evaluation (all blocks at once) into Task::InternalForces: one pair of
  /// clock reads per evaluation, not one per level (nullptr: no timing).
  void set_clock(TaskClock* clock) { clock_ = clock; }

 private:
  IndexSet points(const IntegrationBlock& b) const;
  void evaluate_all();
  void sync() { if (sync_) sync_(); }
  void stoermer_verlet_step(double dt);
  void newton_cotes_step(double dt);
  /// Störmer–Verlet: the current forces (s.f) of `points` become their next first half-kick.
  void keep_forces(PointState& s, IndexSet points) const;

  Integrator kind_;
  std::vector<IntegrationBlock> blocks_;
  TaskClock* clock_ = nullptr;
  std::function<void()> sync_;
  std::function<void()> gathered_;
  std::vector<std::int64_t> evaluations_;
  bool restore_momentum_ = false;  // SemiImplicitMomentum on a body with no fixed point
  double previous_dt_ = 0;         // Newton–Cotes: the step u_prev, v_prev are from; 0: none
  std::vector<MomentumBlock> momentum_parts_;  // scratch, one per block
  std::vector<PointState*> momentum_states_;
  std::vector<IntegrationBlock> body_;         // restore_momentum_over
  std::vector<MomentumBlock> body_parts_;      // scratch
  std::vector<PointState*> body_states_;
};

}  // namespace mrsim
