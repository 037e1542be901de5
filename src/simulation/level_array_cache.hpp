#pragma once
// A level's adjacency, Laplacian weights and tets' energy bounds (LevelArrays,
// physics/level_model.hpp) kept between runs beside its spectra (simulation/spectrum_cache.hpp):
// with both, a warm set-up builds liver_probe's four level models in ~9 M instructions instead
// of ~35 M (issue 17). One binary file per level under level_arrays/ in the result cache
// (simulation/result_cache.hpp), keyed by the spectra's key (the mesh, the law, the held points,
// the integrator family and this build), with a checksum; what it holds is checked against the
// mesh before use, so a record that does not fit is said, ignored and written again.
#include <optional>
#include <string>

#include "physics/level_model.hpp"

namespace mrsim {

/// The arrays stored under `key` (spectrum_key()) for `mesh`, or nothing (absent, damaged, or
/// not this mesh's: then a warning).
std::optional<LevelArrays> read_level_arrays(const std::string& key, const TetMesh& mesh);

/// Stores `m`'s arrays under `key`, best effort (a folder that cannot be written: a warning).
void write_level_arrays(const std::string& key, const LevelModel& m);

}  // namespace mrsim
