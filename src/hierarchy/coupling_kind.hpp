#pragma once
namespace mrsim {

// How an active point feels the levels around it (docs/hierarchy.md, "coupling").
enum class Coupling {
  Energy,  // forces are -∂E/∂u of one energy over all levels (ghost forces sent back, Jᵀ):
           // symmetric, stable, momentum exact; a uniform strain leaves small interface forces
  EnergyConsistent,  // the same energy with the interface weights adjusted so that a uniform
                     // strain leaves none (hierarchy/patch_test_weights.hpp): exact patch test
  Force,   // the thesis' rule: each active point uses its whole star with ghost displacements;
           // exact patch test, but the coupled operator is not symmetric (interface flutter)
};

}  // namespace mrsim
