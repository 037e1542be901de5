#include "io/frame_data_check.hpp"

#include <stdexcept>
#include <string>
#include <string_view>

namespace mrsim {
namespace {

void check_size(std::size_t actual, std::size_t expected, std::string_view where,
                std::string_view array) {
  if (actual == expected) return;
  throw std::invalid_argument(std::string(where) + ": " + std::string(array) + " has " +
                              std::to_string(actual) + " values, expected " +
                              std::to_string(expected));
}

// Triangle corners index the points of their own surface: a stray index would make VTK read
// past its point array (no check on its side), so it is refused here.
void check_triangles(std::span<const std::array<int, 3>> triangles, std::size_t points,
                     std::string_view where) {
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (const int corner : triangles[t]) {
      if (corner >= 0 && static_cast<std::size_t>(corner) < points) continue;
      throw std::invalid_argument(std::string(where) + ": triangle " + std::to_string(t) +
                                  " refers to point " + std::to_string(corner) + " of " +
                                  std::to_string(points));
    }
  }
}

}  // namespace

void check_level_view(const LevelFrameView& view, int level) {
  const std::string where = "level_" + std::to_string(level);
  if (view.mesh == nullptr) throw std::invalid_argument(where + ": no mesh");
  const std::size_t n = view.mesh->points.size();
  check_size(view.displacement.size(), n, where, "displacement");
  check_size(view.velocity.size(), n, where, "velocity");
  check_size(view.force.size(), n, where, "force");
  check_size(view.status.size(), n, where, "status");
  check_size(view.time_level.size(), n, where, "time_level");
  check_size(view.criterion.size(), n, where, "criterion");
  check_size(view.mass.size(), n, where, "mass");
  if (!view.simulated.empty())
    check_size(view.simulated.size(), view.mesh->tets.size(), where, "simulated");
  if (!view.simulated_by.empty())
    check_size(view.simulated_by.size(), view.mesh->tets.size(), where, "simulated_by");
  if (!view.calibration_scale.empty())
    check_size(view.calibration_scale.size(), view.mesh->tets.size(), where, "calibration_scale");
}

void check_surface_view(const SurfaceFrameView& surface) {
  constexpr std::string_view where = "surface";
  const std::size_t n = surface.rest.size();
  check_size(surface.displacement.size(), n, where, "displacement");
  check_size(surface.velocity.size(), n, where, "velocity");
  check_size(surface.contact_force.size(), n, where, "contact_force");
  check_size(surface.level.size(), n, where, "level");
  check_triangles(surface.triangles, n, where);
}

void check_tool_view(const ToolFrameView& view, int tool) {
  check_triangles(view.triangles, view.points.size(), "tool " + std::to_string(tool));
}

void check_tool_samples(const ToolSamples& samples, int tool) {
  // `time` sets the length: it is the column a reader counts samples by.
  const std::string where = "tool " + std::to_string(tool) + " samples";
  const std::size_t n = samples.time.size();
  check_size(samples.position.size(), n, where, "position");
  check_size(samples.orientation.size(), n, where, "orientation");
  check_size(samples.force.size(), n, where, "force");
  check_size(samples.contacts.size(), n, where, "contacts");
}

void check_frame_record(const FrameRecord& record, std::span<const std::size_t> points_per_level,
                        std::size_t time_levels, std::size_t tools) {
  const std::size_t levels = points_per_level.size();
  const std::string where = "frame " + std::to_string(record.frame);
  check_size(record.time_levels.size(), time_levels, where, "time_levels");
  check_size(record.time_level_evaluations.size(), time_levels, where, "time_level_evaluations");
  check_size(record.tool_force.size(), tools, where, "tool_force");
  check_size(record.active.size(), levels, where, "active");
  check_size(record.ghosts.size(), levels, where, "ghosts");
  check_size(record.force_evaluations.size(), levels, where, "force_evaluations");
  check_size(record.tet_updates.size(), levels, where, "tet_updates");
  check_size(record.status.size(), levels, where, "status (levels)");
  for (std::size_t k = 0; k < levels; ++k) {
    check_size(record.status[k].size(), points_per_level[k],
               where + ", level_" + std::to_string(k), "status");
  }
}

}  // namespace mrsim
