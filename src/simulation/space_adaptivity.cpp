#include "simulation/space_adaptivity.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "physics/laplacian_criterion.hpp"

namespace mrsim {

namespace {

// More than half of p's same-level neighbours q satisfy `holds(q)`.
template <class Pred>
bool most_neighbours(const HierarchicalSimulation& sim, int l, int p, Pred holds) {
  const PointAdjacency& adj = sim.model(l).adj;
  int n = 0;
  for (int e = adj.nbr_start[p]; e < adj.nbr_start[p + 1]; ++e) n += holds(adj.nbr[e]);
  return 2 * n > adj.nbr_start[p + 1] - adj.nbr_start[p];
}

// More than half of p's same-level neighbours are subdivided.
bool surrounded(const HierarchicalSimulation& sim, int l, int p) {
  return most_neighbours(sim, l, p, [&](int q) { return sim.hierarchy().subdivided(l, q); });
}

}  // namespace

SpaceAdaptivity::SpaceAdaptivity(const SpaceAdaptivitySettings& settings,
                                 const HierarchicalSimulation& sim)
    : s_(settings),
      criterion_(sim.num_levels()),
      split_frame_(sim.num_levels()),
      calm_streak_(sim.num_levels()),
      contact_(sim.num_levels()) {
  s_.max_level = std::min(s_.max_level, sim.num_levels() - 1);
  for (int l = 0; l < sim.num_levels(); ++l) {
    criterion_[l].assign(sim.model(l).num_points(), 0.0);
    split_frame_[l].assign(sim.model(l).num_points(), -1);
    calm_streak_[l].assign(sim.model(l).num_points(), 0);
    contact_[l].assign(sim.model(l).num_points(), 0);
  }
  if (s_.predict_horizon > 0) {
    predicted_.resize(sim.num_levels());
    scratch_.resize(sim.num_levels());
    for (int l = 0; l < sim.num_levels(); ++l) {
      predicted_[l].assign(sim.model(l).num_points(), Vec3::Zero());
      scratch_[l].assign(sim.model(l).num_points(), Vec3::Zero());
    }
  }
}

void SpaceAdaptivity::restore(std::vector<std::vector<int>> split_frames,
                              std::vector<std::vector<int>> calm_streaks) {
  bool fits = split_frames.size() == split_frame_.size() &&
              calm_streaks.size() == calm_streak_.size();
  for (size_t l = 0; fits && l < split_frames.size(); ++l)
    fits = split_frames[l].size() == split_frame_[l].size() &&
           calm_streaks[l].size() == calm_streak_[l].size();
  if (!fits) throw std::invalid_argument("SpaceAdaptivity::restore: another hierarchy's frames");
  split_frame_ = std::move(split_frames);
  calm_streak_ = std::move(calm_streaks);
}

void SpaceAdaptivity::mark_contact_region(const HierarchicalSimulation& sim) {
  for (const auto& [l, p] : region_) contact_[l][p] = 0;
  region_.clear();
  if (s_.contact_lookahead <= 0) return;
  sim.contact_region(s_.contact_lookahead, region_);
  for (const auto& [l, p] : region_) contact_[l][p] = 1;
}

// The largest criterion among the children of subdivided point p of level l.
double SpaceAdaptivity::worst_child(const HierarchicalSimulation& sim, int l, int p) const {
  double worst = 0;
  for (int c : sim.hierarchy().links(l).children.row(p))
    worst = std::max(worst, criterion_[l + 1][c]);
  return worst;
}

// A subdivided point stays subdivided while a point it activated moves skin near a tool.
bool SpaceAdaptivity::holds_contact(const HierarchicalSimulation& sim, int l, int p) const {
  for (int q : sim.hierarchy().links(l).active_set.row(p))
    if (contact_[l + 1][q]) return true;
  return false;
}

void SpaceAdaptivity::evaluate(const HierarchicalSimulation& sim) {
  for (int l = 0; l < sim.num_levels(); ++l) {
    std::fill(criterion_[l].begin(), criterion_[l].end(), 0.0);
    const LevelModel& m = sim.model(l);
    const std::vector<int>& active = sim.lists().active(l);
    const Vec3* u = sim.state(l).u.data();
    if (const std::vector<int>* tets = sim.live_tets(l))  // each tet's gradient once
      corrected_criterion(m, active, *tets, u, gradients_, criterion_[l].data());
    else
      for (int p : active) criterion_[l][p] = m.mean_edge[p] * corrected_laplacian(m, p, u).norm();
  }
  if (s_.predict_horizon > 0) add_predicted(sim);
}

// c of the displacement predicted predict_horizon ahead from the applied loads alone,
// u + ½ T² (g + f_load/m) on the free active points, f_load the largest load the profiles
// reach within predict_window (as many frames as levels: a load ramped in from zero reaches
// the finest level before it bends the body), interpolated to the
// ghosts as a step interpolates u: where the loads are about to bend the body, c rises before the frame that
// bends it. Neither the velocity nor the internal forces enter: over a frame they would
// multiply every fast vibration by up to (ωT)²/2 (hundreds on the liver) and refine wherever it
// trembles; nor do the contacts, whose penalty force the body balances at once (the tools
// have their own look-ahead). docs/hierarchy.md "Refining ahead of loads".
void SpaceAdaptivity::add_predicted(const HierarchicalSimulation& sim) {
  const double T = s_.predict_horizon;
  std::vector<LevelFields> fields(sim.num_levels());
  for (int l = 0; l < sim.num_levels(); ++l) {
    const PointState& st = sim.state(l);
    for (int p : sim.lists().active(l))
      predicted_[l][p] = st.free_point[p] ? st.u[p] + (0.5 * T * T) * s_.gravity : st.u[p];
    fields[l] = {predicted_[l].data(), scratch_[l].data()};
  }
  sim.for_each_surface_load_ahead(std::max(T, s_.predict_window), [&](int l, int p, const Vec3& f) {
    const PointState& st = sim.state(l);
    if (st.free_point[p]) predicted_[l][p] += (0.5 * T * T * st.inv_mass[p]) * f;
  });
  sim.interpolate_ghosts(fields);
  for (int l = 0; l < sim.num_levels(); ++l) {
    const LevelModel& m = sim.model(l);
    for (int p : sim.lists().active(l))
      criterion_[l][p] = std::max(
          criterion_[l][p], m.mean_edge[p] * corrected_laplacian(m, p, predicted_[l].data()).norm());
  }
}

void SpaceAdaptivity::split_worst(HierarchicalSimulation& sim, int frame,
                                  std::vector<HierarchyEvent>& events) {
  // (-c, level, point): points near a tool first, then the worst criterion; stable.
  std::vector<std::tuple<double, int, int>> worst;
  for (int l = 0; l < s_.max_level; ++l)
    for (int p : sim.lists().active(l)) {
      if (!sim.hierarchy().can_split(l, p)) continue;
      if (contact_[l][p])
        worst.emplace_back(-std::numeric_limits<double>::infinity(), l, p);
      else if (criterion_[l][p] > s_.refine_above)
        worst.emplace_back(-criterion_[l][p], l, p);
    }
  std::sort(worst.begin(), worst.end());
  std::int64_t active = 0;
  for (int l = 0; l < sim.num_levels(); ++l) active += sim.lists().active(l).size();
  for (const auto& [neg_c, l, p] : worst) {
    if (!sim.hierarchy().can_split(l, p)) continue;
    if (!split_within_cap(sim, l, p, frame, active, events)) break;
  }
  split_islands(sim, frame, active, events);
}

void SpaceAdaptivity::split_islands(HierarchicalSimulation& sim, int frame, std::int64_t& active,
                                    std::vector<HierarchyEvent>& events) {
  for (int l = 0; l < s_.max_level; ++l)
    for (int p : sim.lists().active(l)) {
      if (!sim.hierarchy().can_split(l, p) || !surrounded(sim, l, p)) continue;
      if (!split_within_cap(sim, l, p, frame, active, events)) return;
    }
}

// Splits p unless that would take the active points over the cap (then returns false).
bool SpaceAdaptivity::split_within_cap(HierarchicalSimulation& sim, int l, int p, int frame,
                                       std::int64_t& active, std::vector<HierarchyEvent>& events) {
  const auto added = static_cast<std::int64_t>(sim.hierarchy().links(l).active_set.row(p).size());
  if (s_.max_active_points > 0 && active + added > s_.max_active_points) return false;
  sim.split(l, p);
  active += added;
  split_frame_[l][p] = frame;
  calm_streak_[l][p] = 0;
  events.push_back({frame, "split", l, p});
  return true;
}

// At a frame end: one more calm frame for every subdivided point whose children are all calm
// now, none for the others (a single swing above coarsen_below starts the count again). A child
// that is itself subdivided has no criterion of its own: it is calm when its children are, so
// the finest level is counted first. With calm_frames 1 this is the frame-end rule exactly (a
// point above a subdivided child cannot merge before that child does).
void SpaceAdaptivity::count_calm(const HierarchicalSimulation& sim) {
  for (int l = sim.num_levels() - 2; l >= 0; --l)
    for (int p : sim.lists().ghost_sub(l)) {
      bool calm = true;
      for (int c : sim.hierarchy().links(l).children.row(p)) {
        const bool below = sim.hierarchy().subdivided(l + 1, c)
                               ? calm_streak_[l + 1][c] > 0
                               : criterion_[l + 1][c] < s_.coarsen_below;
        calm = calm && below;
      }
      calm_streak_[l][p] = calm ? calm_streak_[l][p] + 1 : 0;
    }
}

// A subdivided point merges when its children have been calm (criterion below coarsen_below)
// at the last calm_frames frame ends, after its dwell time, unless more than half of its
// neighbours stay subdivided (the island rule, seen from the other side): neighbours that merge
// in the same pass do not count, so a calm refined region merges whole instead of being held by
// its own interior.
void SpaceAdaptivity::merge_calm(HierarchicalSimulation& sim, int frame,
                                 std::vector<HierarchyEvent>& events) {
  count_calm(sim);
  std::vector<int> calm;
  for (int l = sim.num_levels() - 2; l >= 0; --l) {  // leaves first
    calm.clear();
    for (int p : sim.lists().ghost_sub(l)) {  // sorted: so is `calm`
      if (split_frame_[l][p] >= 0 && frame - split_frame_[l][p] < s_.min_dwell_frames) continue;
      if (!sim.hierarchy().can_merge(l, p) || holds_contact(sim, l, p)) continue;
      if (calm_streak_[l][p] >= s_.calm_frames) calm.push_back(p);
    }
    auto staying = [&](int q) {
      return sim.hierarchy().subdivided(l, q) && !std::binary_search(calm.begin(), calm.end(), q);
    };
    std::vector<int> merging;
    for (int p : calm)
      if (!most_neighbours(sim, l, p, staying)) merging.push_back(p);
    for (int p : merging) {
      if (!sim.hierarchy().can_merge(l, p)) continue;
      sim.merge(l, p);
      events.push_back({frame, "merge", l, p});
    }
  }
}

// Over budget: a quarter (at least one) of the subdivided points that can merge now, the
// calmest children first, merge whatever their criterion and dwell time; leaves only, so
// each frame over budget sheds one layer of the finest refinement.
void SpaceAdaptivity::shed(HierarchicalSimulation& sim, int frame,
                           std::vector<HierarchyEvent>& events) {
  std::vector<std::tuple<double, int, int>> calmest;
  for (int l = 0; l + 1 < sim.num_levels(); ++l)
    for (int p : sim.lists().ghost_sub(l)) {
      if (!sim.hierarchy().can_merge(l, p)) continue;
      calmest.emplace_back(worst_child(sim, l, p), l, p);
    }
  std::sort(calmest.begin(), calmest.end());
  const std::size_t n = calmest.empty() ? 0 : std::max<std::size_t>(1, calmest.size() / 4);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& [worst, l, p] = calmest[i];
    if (!sim.hierarchy().can_merge(l, p)) continue;
    sim.merge(l, p);
    events.push_back({frame, "merge", l, p});
  }
}

void SpaceAdaptivity::update(HierarchicalSimulation& sim, int frame,
                             std::vector<HierarchyEvent>& events, BudgetRule budget) {
  evaluate(sim);
  if (!s_.enabled || sim.num_levels() == 1) return;
  mark_contact_region(sim);
  if (budget == BudgetRule::Free) split_worst(sim, frame, events);
  if (budget == BudgetRule::Shed) shed(sim, frame, events);
  merge_calm(sim, frame, events);
  apply(sim, frame, events);
}

void SpaceAdaptivity::split_within_frame(HierarchicalSimulation& sim, int frame,
                                         std::vector<HierarchyEvent>& events) {
  evaluate(sim);
  if (!s_.enabled || sim.num_levels() == 1) return;
  mark_contact_region(sim);
  split_worst(sim, frame, events);
  apply(sim, frame, events);
}

// Only after a split or merge (issue 17: rebuild at topology changes only): the supports follow
// the statuses, and applying no change would rebuild the same lists, masses and stable steps
// and restart the integrators (Störmer–Verlet's saved half-kick force and Newton–Cotes' step
// before lost for nothing).
void SpaceAdaptivity::apply(HierarchicalSimulation& sim, int frame,
                            std::vector<HierarchyEvent>& events) {
  if (!sim.changes_pending()) return;
  const int released = sim.collect_garbage();
  if (released > 0) events.push_back({frame, "gc", -1, released});
  sim.apply_changes();
}

}  // namespace mrsim
