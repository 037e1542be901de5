#include "meshing/surface_input.hpp"

#include "meshing/surface_checks.hpp"
#include "meshing/surface_readers.hpp"
#include "meshing/surface_source.hpp"

namespace mrsim {

SurfaceInput load_surface_input(const std::filesystem::path& path, const std::string& units,
                                double metres_per_unit, double feature_angle_deg) {
  SurfaceMesh surface = read_surface(path);
  const std::size_t file_triangles = surface.triangles.size();
  const std::string name = path.filename().string();
  SurfaceCheckReport checks = check_surface(surface, path.string());
  scale_surface(surface, metres_per_unit);
  const double volume = checks.enclosed_volume * metres_per_unit * metres_per_unit * metres_per_unit;
  nlohmann::ordered_json description{
      {"input", name},
      {"units", units},
      {"points", surface.points.size()},
      {"triangles", file_triangles},
      {"merged_points", checks.merged_points},
      {"reoriented_triangles", checks.flipped_triangles},
      {"genus", checks.genus},
      {"enclosed_volume_m3", volume},
      {"area_m2", checks.area * metres_per_unit * metres_per_unit},
      {"feature_angle_deg", feature_angle_deg},
  };
  return {std::make_unique<SurfaceSource>(std::move(surface), volume, name, feature_angle_deg),
          std::move(description)};
}

}  // namespace mrsim
