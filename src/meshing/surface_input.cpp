#include "meshing/surface_input.hpp"

#include <string>

#include "core/log.hpp"
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
  // Said, not only recorded: a surface exported with some facets the wrong way round may hide
  // a modelling error (issue 18 defect 9).
  if (checks.flipped_triangles > 0)
    warn(path.string() + ": " + std::to_string(checks.flipped_triangles) + " of " +
         std::to_string(surface.triangles.size()) +
         " triangles faced inwards and were reoriented (outward normals follow the enclosed "
         "volume)");
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
