#pragma once
// The calibration of a hierarchy's coarse levels (hierarchy/level_calibration.hpp) costs up to
// a few seconds at set-up (one factorisation of the finest level, one per fit iteration of each
// coarser level); sweeps and repeated runs of one hierarchy pay it once. The result is kept in
// the result cache (simulation/result_cache.hpp) under calibration/,
// one binary file per key (read_cached_bytes: a header with the key and a checksum): a hash of
// everything the fit reads (each level's points, tets and fixed flags, λ, μ, density, the
// fit's version). The doubles are stored as they are, so a run that reads the cache is the run
// that computed it, bit for bit.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hierarchy/level_calibration.hpp"

namespace mrsim {

/// 16 hex digits (FNV-1a 64 of the fit's inputs).
std::string calibration_key(const std::vector<const TetMesh*>& meshes, const MaterialLaw& law,
                            const std::vector<std::vector<std::uint8_t>>& fixed,
                            CalibrationKind kind = CalibrationKind::Orthotropic);

/// The folder of the cache files; empty when no folder can be named (no HOME).
std::filesystem::path calibration_cache_dir();

/// The cached calibration of `key`, or nothing (absent, unreadable, not of one entry per mesh or
/// with per-tet factors not one per tet; a damaged file is reported by a warning and ignored).
std::optional<std::vector<LevelCalibration>> read_cached_calibration(
    const std::filesystem::path& dir, const std::string& key,
    const std::vector<const TetMesh*>& meshes);

/// Stores it (best effort: a folder that cannot be written gives a warning, never an error).
/// Written under a temporary name unique to the process, then renamed: concurrent runs of a
/// sweep never see a torn file.
void write_cached_calibration(const std::filesystem::path& dir, const std::string& key,
                              const std::vector<LevelCalibration>& calibration);

}  // namespace mrsim
