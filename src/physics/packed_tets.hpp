#pragma once
// The tets a partly simulated level evaluates, copied contiguously (vertices, ∇N, volume, per-tet scales) at each
// topology change, in their ascending id order. The one-thread Green–Lagrange pass then streams
// them instead of striding through the whole level's arrays between other levels' passes: on the
// bundled liver_probe the adaptive run's kernel took 74 ns per tet update against 61 for the
// uniform finest level (issue 17 point 1; docs/performance.md). Same tets, same order, so each
// point receives its terms in the same order: the same bits.
#include <vector>

#include "core/index_set.hpp"
#include "physics/green_kernel_data.hpp"
#include "physics/tet_geometry.hpp"

namespace mrsim {

struct PackedTets {
  const int* source = nullptr;  // the list packed (its data), to recognise it in a pass
  int count = 0;
  std::vector<Tet> tets;
  std::vector<TetGradients> grad;
  std::vector<double> volume;
  std::vector<StiffnessScales> scales;  // TetGeometry::scales (empty without them)
  // ∇N and the scales again in blocks of kPackedBlock tets, component by component
  // (GreenKernelData::grad_blocks, scale_blocks): what the kernel reads.
  std::vector<double> grad_blocks, scale_blocks;
  // Per packed tet, gathered from the level's weights at the first pass after pack() or after
  // they were edited (LevelForceField::edit_tet_weights()), never per step.
  std::vector<double> weight;
  const double* weight_source = nullptr;  // the weights gathered; nullptr: none yet (stale)
  std::vector<int> order;      // 0 .. count-1: the kernel's tet list
  // Every vertex of these tets is among the points each pass over them is given: a coupled
  // level's live tets and its active points and ghosts (method.md §4.9 invariant I2). The pass
  // then writes without the points' mask (a lookup per vertex).
  bool closed = false;

  /// Copies the tets `ids` (ascending) of `geo`; `ids` must stay the list passed in later.
  /// `closed`: see above.
  void pack(const TetGeometry& geo, const std::vector<int>& ids, bool closed = false);
  void clear();
  /// Is `tets` the list packed?
  bool packs(IndexSet tets) const { return count > 0 && tets.ids == source && tets.count == count; }
};

}  // namespace mrsim
