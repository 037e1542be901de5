#include "meshing/level_outputs.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "io/atomic_file.hpp"
#include "meshing/tet_vtu_writer.hpp"
#include "mrsim/version.hpp"

namespace mrsim {
namespace {

using Json = nlohmann::ordered_json;

Json radius_ratio_json(const TetQuality& q) {
  Json bins = Json::array();
  for (int b = 0; b <= kRadiusRatioBins; ++b) bins.push_back(static_cast<double>(b) / kRadiusRatioBins);
  Json counts = Json::array();
  for (std::size_t c : q.radius_ratio_histogram) counts.push_back(c);
  return {{"min", q.min_radius_ratio}, {"mean", q.mean_radius_ratio}, {"histogram_edges", bins}, {"histogram_counts", counts}};
}

Json level_json(const LevelRecord& r, std::size_t k, double reference_volume, const std::filesystem::path& prefix) {
  const TetQuality& q = r.level.quality;
  Json level = {
      {"level", k},
      {"file", level_file(prefix, k).filename().string()},
      {"requested_tets", r.requested_tets},
      {"tets", q.tets},
      {"points", q.points},
      {"boundary_triangles", q.boundary_triangles},
      {"count_deviation", static_cast<double>(q.tets) / static_cast<double>(r.requested_tets) - 1.0},
      {"within_tolerance", r.level.within_tolerance},
      {"min_dihedral_deg", q.min_dihedral_deg},
      {"max_dihedral_deg", q.max_dihedral_deg},
      {"radius_ratio", radius_ratio_json(q)},
      {"volume_m3", q.volume},
      {"volume_error", q.volume / reference_volume - 1.0},
      {"volume_error_before_matching", r.level.raw_volume / reference_volume - 1.0},
      {"boundary_offset_m", r.level.boundary_offset},
      {"edge_length_m", {{"min", q.min_edge}, {"mean", q.mean_edge}, {"max", q.max_edge}}},
      {"mesh_size_m", r.level.settings.size},
      {"algorithm", algorithm_name(r.level.settings.algorithm)},
      {"candidates", r.level.candidates},
      {"failed_attempts", r.level.failed_attempts},
  };
  // Only levels made by the fallback say so: the reports of other inputs keep their bytes.
  if (r.level.simplified_surface) level["surface"] = "simplified by edge collapses, kept by gmsh (not remeshed)";
  return level;
}

Json resolution_ratios(const std::vector<LevelRecord>& levels) {
  Json ratios = Json::array();
  for (std::size_t k = 1; k < levels.size(); ++k) {
    const TetQuality& coarse = levels[k - 1].level.quality;
    const TetQuality& fine = levels[k].level.quality;
    ratios.push_back({{"levels", {k - 1, k}},
                      {"mean_edge_ratio", coarse.mean_edge / fine.mean_edge},
                      {"cube_root_tet_ratio", std::cbrt(static_cast<double>(fine.tets) / static_cast<double>(coarse.tets))}});
  }
  return ratios;
}

}  // namespace

std::filesystem::path level_file(const std::filesystem::path& prefix, std::size_t k) {
  std::filesystem::path file = prefix;
  file += "_L" + std::to_string(k) + ".vtu";
  return file;
}

nlohmann::ordered_json quality_report(const std::vector<LevelRecord>& levels, const nlohmann::ordered_json& source,
                                      double reference_volume, const std::filesystem::path& prefix) {
  Json report;
  report["generator"] = std::string("mrsim mesh ") + kVersion;
  report["source"] = source;
  report["reference_volume_m3"] = reference_volume;
  report["levels"] = Json::array();
  for (std::size_t k = 0; k < levels.size(); ++k) report["levels"].push_back(level_json(levels[k], k, reference_volume, prefix));
  report["resolution_ratios"] = resolution_ratios(levels);
  return report;
}

std::string levels_snippet(const std::vector<LevelRecord>& levels, const std::string& source_name,
                           const std::filesystem::path& prefix) {
  std::ostringstream out;
  out << "# Levels of " << source_name << ", coarse to fine, written by mrsim mesh " << kVersion << ".\n"
      << "# The `object:` block of a scenario; mesh paths are relative to this file's folder.\n"
      << "# It lists every level (a scenario takes 1 to 7) and can be used as it is.\n"
      << "object:\n  levels:\n";
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const TetQuality& q = levels[k].level.quality;
    char comment[96];
    std::snprintf(comment, sizeof comment, "   # %zu tets, %zu points, min dihedral %.1f deg", q.tets, q.points,
                  q.min_dihedral_deg);
    out << "    - mesh: " << level_file(prefix, k).filename().string() << comment << '\n';
  }
  out << "  units: m\n";
  return out.str();
}

LevelOutputs write_level_outputs(const std::vector<LevelRecord>& levels, const nlohmann::ordered_json& source,
                                 const std::string& source_name, double reference_volume,
                                 const std::filesystem::path& prefix) {
  LevelOutputs outputs;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    outputs.meshes.push_back(level_file(prefix, k));
    write_tet_vtu(outputs.meshes.back(), levels[k].level.mesh);
  }
  outputs.quality = prefix;
  outputs.quality += "_quality.json";
  write_file_atomically(outputs.quality, quality_report(levels, source, reference_volume, prefix).dump(2) + "\n");
  outputs.snippet = prefix;
  outputs.snippet += "_levels.yaml";
  write_file_atomically(outputs.snippet, levels_snippet(levels, source_name, prefix));
  return outputs;
}

}  // namespace mrsim
