#include "simulation/level_force_field.hpp"

#include <algorithm>

#include "core/parallel.hpp"
#include "core/sorted_merge.hpp"
#include "hierarchy/tet_shares.hpp"

namespace mrsim {

LevelForceField::LevelForceField(const LevelModel& model, const Vec3& gravity)
    : model_(model), gravity_(gravity) {
  weight_.resize(model.num_points());
  for (int i = 0; i < model.num_points(); ++i) weight_[i] = model.mass[i] * gravity;
  tet_mark_.assign(model.num_tets(), 0);
  ws_.reserve_for(model);
}

void LevelForceField::weigh(const std::vector<int>& points,
                            const std::vector<PointInertia>& inertia) {
  for (int p : points) weight_[p] = inertia[p].gravity_mass * gravity_;
}

void LevelForceField::serve(const std::vector<int>* points) {
  points_ = points;
  refresh_tets();
}

void LevelForceField::couple(const Hierarchy* h, const StatusLists* lists, int level) {
  hierarchy_ = h;
  lists_ = lists;
  level_ = level;
  share_.assign(model_.num_tets(), 0.0);
  serve(&lists->active(level));
}

void LevelForceField::refresh_tets() {
  if (hierarchy_) {
    refresh_coupling();
  } else if (points_ && model_.law.strain == StrainMeasure::GreenLagrange) {
    live_tets(model_, IndexSet::of(*points_), tet_mark_, tets_);
  }
  // Part of the level: its tets streamed from a contiguous copy (physics/packed_tets.hpp).
  if (model_.law.strain == StrainMeasure::GreenLagrange && !tets_.empty() &&
      static_cast<int>(tets_.size()) < model_.num_tets())
    ws_.packed.pack(model_.geo, tets_, /*closed=*/hierarchy_ != nullptr);
  else
    ws_.packed.clear();
}

// A level without ghosts has only whole tets (all four vertices active, invariant I2), so the
// plain per-point path gives the same forces; the weighted path runs only at interfaces.
void LevelForceField::refresh_coupling() {
  for (int t : tets_) share_[t] = 0.0;
  live_tets(model_, IndexSet::of(*points_), tet_mark_, tets_);
  const auto& sub = lists_->ghost_sub(level_);
  const auto& iface = lists_->ghost_iface(level_);
  weighted_ = !sub.empty() || !iface.empty();
  gathered_.clear();
  if (!weighted_) return;
  active_tet_shares(*hierarchy_, level_, tets_, share_);
  std::vector<int> ghosts;
  std::merge(sub.begin(), sub.end(), iface.begin(), iface.end(), std::back_inserter(ghosts));
  std::merge(points_->begin(), points_->end(), ghosts.begin(), ghosts.end(),
             std::back_inserter(gathered_));
  if (model_.law.strain == StrainMeasure::Cauchy) ws_.reserve_for(model_, true);
}

IndexSet LevelForceField::points() const {
  if (subset_) return IndexSet::of(subset_->served);
  return points_ ? IndexSet::of(*points_) : IndexSet::all(model_.num_points());
}

void LevelForceField::subset_for(const std::vector<int>& served, const std::vector<int>& ghosts,
                                 FieldSubset& out) {
  out.served = served;
  out.gathered.clear();
  out.tets.clear();
  if (weighted_) {
    std::merge(served.begin(), served.end(), ghosts.begin(), ghosts.end(),
               std::back_inserter(out.gathered));
    live_tets(model_, IndexSet::of(out.gathered), tet_mark_, out.tets);
    std::erase_if(out.tets, [&](int t) { return share_[t] == 0; });
  } else if (model_.law.strain == StrainMeasure::GreenLagrange) {
    live_tets(model_, IndexSet::of(served), tet_mark_, out.tets);
  }
}

void merge_subsets(const FieldSubset& a, const FieldSubset& b, FieldSubset& out) {
  merge_sorted(a.served, b.served, out.served);
  merge_sorted(a.gathered, b.gathered, out.gathered);
  merge_sorted(a.tets, b.tets, out.tets);
}

std::int64_t LevelForceField::evaluate(const Vec3* u, const Vec3* v, Vec3* f) {
  const IndexSet pts = points();
  IndexSet tets = points_ ? IndexSet::of(tets_) : IndexSet::all(model_.num_tets());
  IndexSet gathered = IndexSet::of(gathered_);
  if (subset_) {
    tets = IndexSet::of(subset_->tets);
    gathered = IndexSet::of(subset_->gathered);
  }
  if (weighted_)
    weighted_internal_forces(model_, gathered, tets, share_.data(), u, v, f, ws_);
  else
    internal_forces(model_, pts, tets, u, v, f, ws_);
  if (weighted_ || model_.law.strain == StrainMeasure::GreenLagrange) tet_updates_ += tets.count;
  const int n = pts.count;
  if (external_)
    parallel_for(n, [&](int k) {
      f[pts[k]] += weight_[pts[k]];
      f[pts[k]] += external_[pts[k]];  // in this order, as when these were two loops
    });
  else
    parallel_for(n, [&](int k) { f[pts[k]] += weight_[pts[k]]; });
  return n;
}

}  // namespace mrsim
