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
}

void check_frame_record(const FrameRecord& record, std::span<const std::size_t> points_per_level,
                        std::size_t time_levels) {
  const std::size_t levels = points_per_level.size();
  const std::string where = "frame " + std::to_string(record.frame);
  check_size(record.time_levels.size(), time_levels, where, "time_levels");
  check_size(record.time_level_evaluations.size(), time_levels, where, "time_level_evaluations");
  check_size(record.active.size(), levels, where, "active");
  check_size(record.ghosts.size(), levels, where, "ghosts");
  check_size(record.force_evaluations.size(), levels, where, "force_evaluations");
  check_size(record.status.size(), levels, where, "status (levels)");
  for (std::size_t k = 0; k < levels; ++k) {
    check_size(record.status[k].size(), points_per_level[k],
               where + ", level_" + std::to_string(k), "status");
  }
}

}  // namespace mrsim
