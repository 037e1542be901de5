#pragma once
namespace mrsim {

// One-force-evaluation-per-step schemes of method.md §5.1 and §5.3.
enum class Integrator {
  ModifiedEuler,   // symplectic Euler: v += dt f/m; u += dt v
  StoermerVerlet,  // kick-drift-kick (velocity Verlet); positions identical to modified Euler
  SemiImplicit,    // eq. (5.1): v += dt f/m; v = (I - dt²J/m)^-1 v; u += dt v
  SemiImplicitMomentum,  // eq. (5.1), then a free body gets back the linear and angular
                         // momentum the filter removed (time/momentum_restoration.hpp)
  NewtonCotes,  // the thesis' third scheme (§4.3, "much less stable"), read as the open
                // Newton–Cotes (two-step midpoint) rule: u+ = u- + 2dt v, v+ = v- + 2dt f/m
};

inline bool is_semi_implicit(Integrator kind) {
  return kind == Integrator::SemiImplicit || kind == Integrator::SemiImplicitMomentum;
}

/// Schemes that need the state of the step before (every point on the same step).
inline bool is_two_step(Integrator kind) { return kind == Integrator::NewtonCotes; }

const char* integrator_name(Integrator kind);

}  // namespace mrsim
