#pragma once
// Which level simulates each part of the object, for display (docs/output.md "ParaView"). A
// location belongs to the finest level whose tet there has no inactive vertex (level 0 always
// qualifies): the rule that picks the level moving each skin vertex (contact/skin_map.hpp), so
// the skin's `level` and the tets' `simulated` tell the same story. Each tet is sampled at rest
// with points spread uniformly in it, about one per tet of the finest level's size (so a
// coarse tet that straddles a border between levels is measured at the finest resolution), and
// the samples are located once in every level. Per frame, a tet's share is the fraction of its
// samples its own level owns: Σ share × volume over all levels is the object's volume up to the
// sampling (0.3 % on the bundled liver).
#include <cstdint>
#include <vector>

#include "hierarchy/hierarchy.hpp"
#include "hierarchy/tet_locator.hpp"

namespace mrsim {

class LevelOwnership {
 public:
  /// O(Σ samples × levels) point locations, once; about levels × the finest level's tets
  /// samples in all.
  explicit LevelOwnership(const Hierarchy& h);
  /// The same with each level's locator given (`locators[l]` over level l's mesh).
  LevelOwnership(const Hierarchy& h, const std::vector<TetLocator>& locators);

  /// Takes the hierarchy's current statuses: which tets of each level have no inactive vertex.
  /// O(tets of all levels) when `h` changed a status since the last call (or is another
  /// hierarchy), O(1) otherwise; call it before shares() whenever the statuses may have changed.
  /// Returns whether any tet's coverage changed since the last call (true on the first): the
  /// shares of every level are the same as last time when it did not, so a frame without a
  /// topology change need not ask for them again.
  bool observe(const Hierarchy& h);

  /// For every tet of `level` in the statuses last observed: share[t], the fraction of it
  /// `level` simulates (0–1), and owner[t], the level that simulates most of it (the coarser one
  /// on a tie). O(its samples × levels).
  void shares(int level, std::vector<double>& share, std::vector<std::int8_t>& owner) const;

 private:
  int owner(const std::int32_t* tets_at_sample) const;

  int levels_ = 0;
  std::vector<std::vector<std::int32_t>> start_;  // [level][tet]: its first sample (CSR)
  // where_[l][s * levels_ + m]: the tet of level m holding sample s of level l (m ≥ 1; level 0
  // takes whatever no finer level claims, so where a sample lies in it is never asked).
  std::vector<std::vector<std::int32_t>> where_;
  std::vector<std::vector<std::uint8_t>> covered_;  // [level][tet]: no inactive vertex (observe)
  const Hierarchy* observed_ = nullptr;  // and its Hierarchy::status_changes() then
  std::uint64_t observed_changes_ = 0;
};

}  // namespace mrsim
