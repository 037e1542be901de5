#pragma once
// Reads, converts (to metres) and checks a user's surface file, and describes it for the
// quality report. Every defect throws InputError (exit code 2) before any meshing starts.
#include <filesystem>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "meshing/geometry_source.hpp"

namespace mrsim {

struct SurfaceInput {
  std::unique_ptr<GeometrySource> source;
  nlohmann::ordered_json description;  // file, units, triangle counts, genus, volume...
};

/// `metres_per_unit`: 1 for m, 1e-3 for mm. `feature_angle_deg`: see SurfaceSource.
SurfaceInput load_surface_input(const std::filesystem::path& path, const std::string& units,
                                double metres_per_unit, double feature_angle_deg);

}  // namespace mrsim
