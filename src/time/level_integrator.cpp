#include "time/level_integrator.hpp"

#include "time/explicit_updates.hpp"

namespace mrsim {

const char* integrator_name(Integrator kind) {
  switch (kind) {
    case Integrator::ModifiedEuler: return "modified_euler";
    case Integrator::StoermerVerlet: return "stoermer_verlet";
    case Integrator::SemiImplicit: return "semi_implicit";
  }
  return "?";
}

LevelIntegrator::LevelIntegrator(Integrator kind, ForceField& forces, SemiImplicitFilter filter)
    : kind_(kind), forces_(forces), filter_(std::move(filter)) {}

void LevelIntegrator::evaluate(PointState& s) {
  forces_.evaluate(s.u.data(), s.v.data(), s.f.data());
  evaluations_ += s.size();
}

void LevelIntegrator::start(PointState& s) {
  if (kind_ == Integrator::StoermerVerlet) evaluate(s);
}

void LevelIntegrator::step(PointState& s, double dt) {
  switch (kind_) {
    case Integrator::ModifiedEuler:
      evaluate(s);
      kick(s, dt);
      drift(s, dt);
      break;
    case Integrator::StoermerVerlet:
      // Kick-drift-kick: the force at the end of a step is the one at the start of the next.
      // The damping force is evaluated with the half-step velocity.
      kick(s, 0.5 * dt);
      drift(s, dt);
      evaluate(s);
      kick(s, 0.5 * dt);
      break;
    case Integrator::SemiImplicit:
      evaluate(s);
      kick(s, dt);
      filter_.apply(s);
      drift(s, dt);
      break;
  }
}

}  // namespace mrsim
