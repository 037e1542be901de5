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

namespace {

bool same_mesh(const TetMesh& a, const TetMesh& b) {
  return a.points.size() == b.points.size() && a.tets.size() == b.tets.size() &&
         std::equal(a.tets.begin(), a.tets.end(), b.tets.begin()) &&
         std::equal(a.points.begin(), a.points.end(), b.points.begin());
}

// Two levels that are the same mesh would make a hierarchy with a level that adds nothing
// (the box asked for 8, 20 and 60 tets gave three copies of its 24-tet mesh).
void check_distinct(const std::vector<LevelRecord>& levels, const LevelRecord& next) {
  for (std::size_t k = 0; k < levels.size(); ++k)
    if (same_mesh(levels[k].level.mesh, next.level.mesh))
      throw InputError("--tets: levels L" + std::to_string(k) + " (asked " +
                       std::to_string(levels[k].requested_tets) + ") and L" +
                       std::to_string(levels.size()) + " (asked " +
                       std::to_string(next.requested_tets) + ") came out as the same " +
                       std::to_string(next.level.mesh.tets.size()) +
                       "-tet mesh: this object cannot be meshed that coarsely with different "
                       "counts; ask for fewer or larger levels");
}

}  // namespace

std::vector<LevelRecord> build_levels(const GeometrySource& source, const std::vector<std::size_t>& targets,
                                      const std::function<void(const LevelRecord&)>& on_level) {
  std::vector<LevelRecord> levels;
  for (std::size_t target : targets) {
    const auto start = std::chrono::steady_clock::now();
    LevelRecord record{target, search_level(source, target), 0.0};
    record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    check_distinct(levels, record);
    if (on_level) on_level(record);
    levels.push_back(std::move(record));
  }
  return levels;
}

}  // namespace mrsim
