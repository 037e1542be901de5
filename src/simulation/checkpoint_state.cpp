#include "simulation/checkpoint_state.hpp"

#include <stdexcept>
#include <string>

namespace mrsim {

namespace {

// A checkpoint array must have the size of the state it replaces (empty for an integrator
// that does not use it).
void check_size(const std::vector<Vec3>& into, const std::vector<Vec3>& from, const char* what,
                int l) {
  if (from.size() != into.size())
    throw std::invalid_argument("checkpoint level " + std::to_string(l) + ": " + what + " has " +
                                std::to_string(from.size()) + " entries, the simulation " +
                                std::to_string(into.size()));
}

// Every array of every level fits, before anything is changed.
void check_sizes(const std::vector<PointState>& states, const SimulationCheckpoint& c) {
  for (size_t l = 0; l < states.size(); ++l) {
    const PointState& s = states[l];
    const LevelCheckpoint& level = c.levels[l];
    const int i = static_cast<int>(l);
    check_size(s.u, level.u, "u", i);
    check_size(s.v, level.v, "v", i);
    check_size(s.f, level.f, "f", i);
    check_size(s.f_kick, level.f_kick, "f_kick", i);
    check_size(s.u_prev, level.u_prev, "u_prev", i);
    check_size(s.v_prev, level.v_prev, "v_prev", i);
  }
}

}  // namespace

SimulationCheckpoint HierarchicalSimulation::checkpoint() const {
  SimulationCheckpoint c;
  c.time = time_;
  c.clock = clock_;
  c.external_at = external_at_;
  c.dt = dt_;
  c.frames = frames_;
  c.steps = steps_;
  c.steps_per_frame = steps_per_frame_;
  c.previous_dt = stepper_->previous_dt();
  c.block_evaluations = stepper_->evaluations();
  for (const auto& f : forces_) c.tet_updates.push_back(f->tet_updates());
  if (time_levels_) c.time_level_evaluations = time_levels_->evaluations();
  if (contact_) c.contact_candidates = contact_->candidates();
  for (int l = 0; l < num_levels(); ++l) {
    const PointState& s = states_[l];
    const HierarchyCounters& h = hierarchy_->counters(l);
    LevelCheckpoint& level = c.levels.emplace_back();
    level.u = s.u;
    level.v = s.v;
    level.f = s.f;
    level.f_kick = s.f_kick;
    level.u_prev = s.u_prev;
    level.v_prev = s.v_prev;
    level.subdivided = h.subdivided;
    level.support = h.support;
    level.active_ref = h.active_ref;
    level.ghost_ref = h.ghost_ref;
    if (time_levels_) {
      level.time_level = time_levels_->time_levels()[l];
      level.stable_level = time_levels_->stable_levels()[l];
    }
  }
  return c;
}

// What apply_changes() does after a topology change, from counters instead of splits and
// merges; then the state the run had (forces saved by the integrators included) instead of a
// restarted integrator.
void HierarchicalSimulation::restore(const SimulationCheckpoint& c) {
  const int L = num_levels();
  if (static_cast<int>(c.levels.size()) != L)
    throw std::invalid_argument("checkpoint of " + std::to_string(c.levels.size()) +
                                " levels for a simulation of " + std::to_string(L));
  check_sizes(states_, c);
  if (static_cast<int>(c.tet_updates.size()) != L)
    throw std::invalid_argument("checkpoint with " + std::to_string(c.tet_updates.size()) +
                                " tet-update counters for " + std::to_string(L) + " levels");
  std::vector<HierarchyCounters> counters(L);
  for (int l = 0; l < L; ++l) {
    const LevelCheckpoint& level = c.levels[l];
    counters[l] = {level.subdivided, level.support, level.active_ref, level.ghost_ref};
  }
  hierarchy_->restore(std::move(counters));
  for (int l = 0; l < L; ++l) {
    const LevelCheckpoint& level = c.levels[l];
    PointState& s = states_[l];
    s.u = level.u;
    s.v = level.v;
    s.u_prev = level.u_prev;
    s.v_prev = level.v_prev;
    std::fill(stale_[l].begin(), stale_[l].end(), 0);
  }
  woken_.clear();
  if (contact_) contact_->restore_candidates(c.contact_candidates);
  time_ = c.time;
  clock_ = c.clock;
  dt_ = c.dt;
  frames_ = c.frames;
  steps_ = c.steps;
  steps_per_frame_ = c.steps_per_frame;
  lists_->update(*hierarchy_, hierarchy_->take_touched());
  rebuild_after_topology(c.external_at);
  if (time_levels_) {
    std::vector<std::vector<std::int8_t>> time_level(L), stable_level(L);
    for (int l = 0; l < L; ++l) {
      time_level[l] = c.levels[l].time_level;
      stable_level[l] = c.levels[l].stable_level;
    }
    time_levels_->restore(std::move(time_level), std::move(stable_level), c.time_level_evaluations);
  }
  stepper_->restore(c.block_evaluations, c.previous_dt);
  for (int l = 0; l < L; ++l) forces_[l]->set_tet_updates(c.tet_updates[l]);
  // The forces the outputs show and Störmer–Verlet kicks with are the saved ones.
  for (int l = 0; l < L; ++l) {
    states_[l].f = c.levels[l].f;
    states_[l].f_kick = c.levels[l].f_kick;
  }
}

SimulationCheckpoint take_checkpoint(const HierarchicalSimulation& sim,
                                     const SpaceAdaptivity& adapt) {
  SimulationCheckpoint c = sim.checkpoint();
  for (int l = 0; l < sim.num_levels(); ++l) {
    c.levels[l].split_frame = adapt.split_frames()[l];
    c.levels[l].calm_streak = adapt.calm_streaks()[l];
  }
  return c;
}

void restore_checkpoint(const SimulationCheckpoint& checkpoint, HierarchicalSimulation& sim,
                        SpaceAdaptivity& adapt) {
  sim.restore(checkpoint);
  std::vector<std::vector<int>> split_frames, calm_streaks;
  for (const LevelCheckpoint& level : checkpoint.levels) {
    split_frames.push_back(level.split_frame);
    calm_streaks.push_back(level.calm_streak);
  }
  adapt.restore(std::move(split_frames), std::move(calm_streaks));
}

}  // namespace mrsim
