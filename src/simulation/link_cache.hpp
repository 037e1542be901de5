#pragma once
// The hierarchy's static geometry, kept between runs. The links between levels
// (hierarchy/level_links.hpp) and the skin's binding to every level (contact/skin_binding.hpp)
// depend on the level meshes (and the skin) alone, and locating points in the other levels'
// tets is most of a hierarchy's set-up (liver_probe: about 22 ms of a 72 ms one-frame run, with
// the levels' locators). A run keeps them in the result cache (simulation/result_cache.hpp)
// under links/ and skin_binding/, in binary, keyed by the meshes (and the skin) and this build:
// a later run reads the very arrays the first one computed, and needs no locator unless it
// writes VTK frames (the level ownership locates in them).
#include <functional>
#include <vector>

#include "contact/skin.hpp"
#include "contact/skin_binding.hpp"
#include "hierarchy/level_links.hpp"
#include "hierarchy/tet_locator.hpp"
#include "simulation/result_cache.hpp"

namespace mrsim {

/// The levels' locators, built when first asked for (a cache miss, or the VTK frames).
using LocatorSource = std::function<const std::vector<TetLocator>&()>;

/// The hash of what the links are computed from: the level meshes, in order.
InputHash hierarchy_inputs(const std::vector<HierarchyLevel>& levels);

/// build_level_links() as an earlier run of this build computed it for the same meshes, read
/// from the cache; else computed and stored for the next run (best effort). `reused`: whether
/// the cache served.
std::vector<LevelLinks> cached_level_links(const std::vector<HierarchyLevel>& levels,
                                           const InputHash& meshes, const LocatorSource& locators,
                                           bool* reused = nullptr);

/// bind_skin() likewise, for `skin` over the levels (`finest_in_coarser` as there).
SkinBinding cached_skin_binding(const Skin& skin, const std::vector<HierarchyLevel>& levels,
                                const InputHash& meshes, const Embedding* finest_in_coarser,
                                const LocatorSource& locators, bool* reused = nullptr);

}  // namespace mrsim
