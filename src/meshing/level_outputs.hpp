#pragma once
// What `mrsim mesh -o PREFIX` writes: PREFIX_L0.vtu ... (coarse to fine), PREFIX_quality.json
// (per-level statistics, see docs/meshing.md) and PREFIX_levels.yaml (the `object:` block of
// a scenario listing the levels). Nothing time- or machine-dependent goes into these files, so
// the same input and options give the same bytes.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "meshing/level_set.hpp"

namespace mrsim {

struct LevelOutputs {
  std::vector<std::filesystem::path> meshes;
  std::filesystem::path quality;
  std::filesystem::path snippet;
};

/// File of level k: "<prefix>_L<k>.vtu".
std::filesystem::path level_file(const std::filesystem::path& prefix, std::size_t k);

/// The quality report. `source` describes the input (file or shape, units, surface checks);
/// `reference_volume` (m^3) is what each level's volume is compared with.
nlohmann::ordered_json quality_report(const std::vector<LevelRecord>& levels, const nlohmann::ordered_json& source,
                                      double reference_volume, const std::filesystem::path& prefix);

/// The scenario snippet, with mesh paths relative to the snippet's own folder.
std::string levels_snippet(const std::vector<LevelRecord>& levels, const std::string& source_name,
                           const std::filesystem::path& prefix);

/// Writes everything (each file atomically). Throws RunError on I/O failure.
LevelOutputs write_level_outputs(const std::vector<LevelRecord>& levels, const nlohmann::ordered_json& source,
                                 const std::string& source_name, double reference_volume,
                                 const std::filesystem::path& prefix);

}  // namespace mrsim
