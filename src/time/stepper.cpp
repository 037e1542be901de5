#include "time/stepper.hpp"

#include <stdexcept>
#include <string>

#include "time/explicit_updates.hpp"

namespace mrsim {

const char* integrator_name(Integrator kind) {
  switch (kind) {
    case Integrator::ModifiedEuler: return "modified_euler";
    case Integrator::StoermerVerlet: return "stoermer_verlet";
    case Integrator::SemiImplicit: return "semi_implicit";
    case Integrator::SemiImplicitMomentum: return "semi_implicit_momentum";
    case Integrator::NewtonCotes: return "newton_cotes";
  }
  return "?";
}

Stepper::Stepper(Integrator kind, std::vector<IntegrationBlock> blocks, std::function<void()> sync,
                 std::function<void()> gathered)
    : kind_(kind), blocks_(std::move(blocks)), sync_(std::move(sync)),
      gathered_(std::move(gathered)), evaluations_(blocks_.size(), 0) {
  // Momentum is restored only for a free body: with supports it is not conserved anyway.
  restore_momentum_ = kind_ == Integrator::SemiImplicitMomentum;
  for (const auto& b : blocks_) {
    restore_momentum_ = restore_momentum_ && b.rest;
    for (std::uint8_t free : b.state->free_point) restore_momentum_ = restore_momentum_ && free;
    momentum_states_.push_back(b.state);
    if (kind_ == Integrator::StoermerVerlet) b.state->f_kick.resize(b.state->size(), Vec3::Zero());
    if (kind_ == Integrator::NewtonCotes) {
      b.state->u_prev.resize(b.state->size(), Vec3::Zero());
      b.state->v_prev.resize(b.state->size(), Vec3::Zero());
    }
  }
  momentum_parts_.reserve(blocks_.size());
}

void Stepper::kick_step(double dt) {
  evaluate_all();
  for (auto& b : blocks_) kick(*b.state, points(b), dt * b.dt_scale);
  if (!is_semi_implicit(kind_)) return;
  if (!restore_momentum_) {
    for (auto& b : blocks_) b.filter->apply(*b.state, points(b), dt * b.dt_scale);
    return;
  }
  // Point lists change with splits and merges: their views are taken anew (no allocation, the
  // vectors keep their capacity).
  momentum_parts_.clear();
  for (auto& b : blocks_) momentum_parts_.push_back({b.state, b.rest, points(b)});
  const MomentumSums before = momentum_sums(momentum_parts_);
  // The body: every point (one global step), or all the particles when time levels kick part
  // of it.
  body_parts_.clear();
  for (auto& b : body_) body_parts_.push_back({b.state, b.rest, points(b)});
  const bool whole = body_.empty();
  // The filter sees only the velocity relative to the body's rigid motion, in the body's
  // frame. Filtered whole, a rigid motion would be braked most where K_ii dt²/m is largest, and
  // the lag turned into strain: on a free beam with a slab of cells 8 times thinner, energy
  // grew 2.6- to 40-fold in 0.5 s at 0.12–0.94 of the stable step. And the filter's blocks K_ii
  // are the rest shape's: once the body has turned, R K_ii Rᵀ is its stiffness, so the filter
  // works in the rest frame, (I + dt²K_ii/m)⁻¹ applied to Rᵀ v (the same beam spinning at
  // 2 rad/s diverged at 0.69 of the stable step without it). Time levels: it cannot drag the
  // kicked particles behind the others either. What it still takes from their momentum goes
  // back over the body.
  const MomentumSums body = momentum_sums(whole ? momentum_parts_ : body_parts_);
  const RigidField rigid = rigid_field(body);
  const Mat3 turn = body_rotation(body);
  add_rigid(momentum_parts_, rigid, -1.0, momentum_states_);
  rotate_velocities(momentum_parts_, turn.transpose(), momentum_states_);
  for (auto& b : blocks_) b.filter->apply(*b.state, points(b), dt * b.dt_scale);
  rotate_velocities(momentum_parts_, turn, momentum_states_);
  add_rigid(momentum_parts_, rigid, 1.0, momentum_states_);
  if (whole)
    restore_momentum(momentum_parts_, before, momentum_states_);
  else
    restore_momentum(momentum_parts_, before, body_parts_, body_states_);
}

void Stepper::restore_momentum_over(std::vector<IntegrationBlock> body) {
  body_ = std::move(body);
  body_states_.clear();
  for (const auto& b : body_) body_states_.push_back(b.state);
  body_parts_.reserve(body_.size());
}

// Kick-drift-kick: the force at the end of a point's step is the one of its next first
// half-kick (kept in f_kick); the damping force sees the half-step velocity.
void Stepper::stoermer_verlet_step(double dt) {
  for (auto& b : blocks_) {
    kick(*b.state, b.state->f_kick.data(), points(b), 0.5 * dt * b.dt_scale);
    drift(*b.state, points(b), dt * b.dt_scale);
  }
  sync();
  evaluate_all();
  for (auto& b : blocks_) {
    kick(*b.state, points(b), 0.5 * dt * b.dt_scale);
    keep_forces(*b.state, points(b));
  }
  sync();
}

// Two-step midpoint (open Newton–Cotes) on the first-order system (u, v), one force evaluation
// per step: u+ = u- + 2dt v, v+ = v- + 2dt f(u, v)/m. Undamped it is stable up to dt = 1/ω, half
// the kick–drift limit; with any damping its parasitic root grows (docs/integrators.md). The
// first step after start() or a change of dt is a modified-Euler step.
void Stepper::newton_cotes_step(double dt) {
  evaluate_all();
  const bool first = previous_dt_ != dt;
  for (auto& b : blocks_) two_step_midpoint(*b.state, points(b), dt * b.dt_scale, first);
  previous_dt_ = dt;
  sync();
}

void Stepper::keep_forces(PointState& s, IndexSet points) const {
  if (kind_ == Integrator::StoermerVerlet) save_forces(s, points, s.f_kick.data());
}

IndexSet Stepper::points(const IntegrationBlock& b) const {
  return b.points ? IndexSet::of(*b.points) : IndexSet::all(b.state->size());
}

void Stepper::evaluate_all() {
  {
    const TaskTimer timer(clock_, Task::InternalForces);
    for (size_t k = 0; k < blocks_.size(); ++k) {
      if (!blocks_[k].forces) continue;
      PointState& s = *blocks_[k].state;
      evaluations_[k] += blocks_[k].forces->evaluate(s.u.data(), s.v.data(), s.f.data());
    }
  }
  if (gathered_) gathered_();
}

void Stepper::restore(std::vector<std::int64_t> evaluations, double previous_dt) {
  if (evaluations.size() != evaluations_.size())
    throw std::invalid_argument("Stepper::restore: " + std::to_string(evaluations.size()) +
                                " evaluation counters for " +
                                std::to_string(evaluations_.size()) + " blocks");
  evaluations_ = std::move(evaluations);
  previous_dt_ = previous_dt;
}

void Stepper::start() {
  previous_dt_ = 0;
  if (kind_ != Integrator::StoermerVerlet) return;
  evaluate_all();
  for (auto& b : blocks_) keep_forces(*b.state, points(b));
}

void Stepper::step(double dt) {
  switch (kind_) {
    case Integrator::ModifiedEuler:
    case Integrator::SemiImplicit:
    case Integrator::SemiImplicitMomentum:
      kick_step(dt);
      for (auto& b : blocks_) drift(*b.state, points(b), dt * b.dt_scale);
      sync();
      break;
    case Integrator::StoermerVerlet:
      stoermer_verlet_step(dt);
      break;
    case Integrator::NewtonCotes:
      newton_cotes_step(dt);
      break;
  }
}

}  // namespace mrsim
