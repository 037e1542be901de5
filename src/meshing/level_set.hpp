#pragma once
// A hierarchy of independent tet meshes of one object, coarse to fine: one size search per
// requested tet count.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "meshing/geometry_source.hpp"
#include "meshing/size_search.hpp"

namespace mrsim {

struct LevelRecord {
  std::size_t requested_tets = 0;
  LevelMesh level;
  double seconds = 0.0;  // wall time of this level's search (reported, never written to files)
};

/// Sorted, distinct, each >= 4 (a tet count below that is no mesh). Throws InputError.
std::vector<std::size_t> checked_targets(std::vector<std::size_t> targets);

std::vector<LevelRecord> build_levels(const GeometrySource& source, const std::vector<std::size_t>& targets,
                                      const std::function<void(const LevelRecord&)>& on_level = {});

}  // namespace mrsim
