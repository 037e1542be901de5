#pragma once
namespace mrsim {

// One-force-evaluation-per-step schemes of method.md §5.1 and §5.3.
enum class Integrator {
  ModifiedEuler,   // symplectic Euler: v += dt f/m; u += dt v
  StoermerVerlet,  // kick-drift-kick (velocity Verlet); positions identical to modified Euler
  SemiImplicit,    // eq. (5.1): v += dt f/m; v = (I - dt²J/m)^-1 v; u += dt v
};

const char* integrator_name(Integrator kind);

}  // namespace mrsim
