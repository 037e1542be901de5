#pragma once
// The levels' spectra (LevelSpectra: the Lanczos runs of physics/level_model.cpp) cost a
// sizeable share of a short run's set-up (liver_probe: ~12 ms of its ~65 ms; they grow with the
// finest level). A run keeps them in the result cache (simulation/result_cache.hpp) under
// spectra/, one file per level, keyed by everything they read: the mesh, the law, the held
// points, the integrator family, and this build (any rebuild measures again). The values are
// written as hexadecimal floats, so a run that reads them builds the model the measuring run
// built, bit for bit.
#include <cstdint>
#include <string>
#include <vector>

#include "physics/level_model.hpp"

namespace mrsim {

/// 16 hex digits.
std::string spectrum_key(const TetMesh& mesh, const MaterialLaw& law, bool semi_implicit,
                         const std::vector<std::uint8_t>& held);

/// build_level_model() with the spectra an earlier run of this build measured for the same
/// inputs, read from the cache; else measured, and stored for the next run (best effort).
/// `reused`: set to whether the cache served.
LevelModel cached_level_model(const TetMesh& mesh, const MaterialLaw& law, bool semi_implicit,
                              const std::vector<std::uint8_t>& held, bool* reused = nullptr);

}  // namespace mrsim
