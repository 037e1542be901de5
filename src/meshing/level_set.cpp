#include "meshing/level_set.hpp"

#include <algorithm>
#include <chrono>

#include "core/error.hpp"

namespace mrsim {

std::vector<std::size_t> checked_targets(std::vector<std::size_t> targets) {
  if (targets.empty()) throw InputError("--tets: give at least one tet count, e.g. --tets 30,170,1900");
  for (std::size_t n : targets) {
    if (n < 4) throw InputError("--tets: " + std::to_string(n) + " is too few tets for a mesh (at least 4)");
    if (n > 5'000'000) throw InputError("--tets: " + std::to_string(n) + " tets is beyond what mrsim mesh builds (5e6)");
  }
  std::sort(targets.begin(), targets.end());
  if (std::adjacent_find(targets.begin(), targets.end()) != targets.end()) {
    throw InputError("--tets: every level needs a different tet count");
  }
  return targets;
}

std::vector<LevelRecord> build_levels(const GeometrySource& source, const std::vector<std::size_t>& targets,
                                      const std::function<void(const LevelRecord&)>& on_level) {
  std::vector<LevelRecord> levels;
  for (std::size_t target : targets) {
    const auto start = std::chrono::steady_clock::now();
    LevelRecord record{target, search_level(source, target), 0.0};
    record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (on_level) on_level(record);
    levels.push_back(std::move(record));
  }
  return levels;
}

}  // namespace mrsim
