#include "simulation/time_adaptivity.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/sorted_merge.hpp"

namespace mrsim {

TimeAdaptivity::TimeAdaptivity(const Hierarchy& h, const StatusLists& lists,
                               const std::vector<const LevelModel*>& models,
                               const std::vector<LevelForceField*>& fields,
                               const std::vector<PointState>& states,
                               const std::vector<std::vector<double>>& stable_dt,
                               const TimeLevelRules& rules)
    : h_(h), status_(lists), models_(models), fields_(fields), states_(states),
      stable_dt_(stable_dt), rules_(rules), wc_(rules.max_level), K_(rules.max_level) {
  const int L = num_levels(), levels = rules.max_level + 1;
  for (int l = 0; l < L; ++l) {
    time_level_.emplace_back(models_[l]->num_points(), std::int8_t{-1});
    stable_level_.emplace_back(models_[l]->num_points(), std::int8_t{0});
    delta_max_.emplace_back(models_[l]->num_points(), -1.0f);
    reach_.emplace_back(models_[l]->num_points(), std::uint8_t{0});
  }
  lists_.assign(levels, std::vector<std::vector<int>>(L));
  subset_.assign(levels, std::vector<FieldSubset>(L));
  need_iface_.assign(levels, std::vector<std::vector<int>>(L));
  need_sub_.assign(levels, std::vector<std::vector<int>>(L));
  stale_.assign(levels, 1);
  merged_.resize(L);
  merged_iface_.resize(L);
  merged_sub_.resize(L);
  selection_.iface.assign(L, nullptr);
  selection_.sub.assign(L, nullptr);
  evaluations_.assign(levels, 0);
  refile();
}

void TimeAdaptivity::refile() {
  for (int l = 0; l < num_levels(); ++l) {
    for (auto& per_k : lists_)
      for (int p : per_k[l])
        if (h_.state(l, p) != NodeState::Active) time_level_[l][p] = -1;
  }
  follow_stable_steps();
  rebuild_lists();
}

// The stable step of every particle follows the topology (interface mass and stiffness) and
// the contact near the tools: a particle whose level became too coarse for it moves finer at
// once. True when one moved.
bool TimeAdaptivity::follow_stable_steps() {
  bool moved = false;
  for (int l = 0; l < num_levels(); ++l)
    for (int p : status_.active(l)) {
      if (!states_[l].free_point[p]) continue;
      stable_level_[l][p] = static_cast<std::int8_t>(stable_time_level(rules_, stable_dt_[l][p]));
      if (time_level_[l][p] >= stable_level_[l][p]) continue;
      time_level_[l][p] = stable_level_[l][p];
      moved = true;
    }
  return moved;
}

void TimeAdaptivity::restable() {
  if (follow_stable_steps()) rebuild_lists();
}

void TimeAdaptivity::rebuild_lists() {
  for (auto& per_k : lists_)
    for (auto& list : per_k) list.clear();
  for (int l = 0; l < num_levels(); ++l)
    for (int p : status_.active(l)) {
      const int k = time_level_[l][p];
      if (k >= 0) lists_[k][l].push_back(p);  // status lists are sorted, so these are too
    }
  std::fill(stale_.begin(), stale_.end(), 1);
}

void TimeAdaptivity::begin_frame() {
  tick_ = 0;
  frame_work_.clear();
  frame_work_.reserve(wc_.ticks_per_frame());  // once: no allocation in the step loop after
}

TimeAdaptivity::SubStep TimeAdaptivity::next() {
  SubStep s;
  s.tick = tick_++;
  const int kc = wc_.coarse_level(s.tick);
  bring_in_pending(s.tick);
  s.levels[0] = K_;
  s.levels[1] = kc;
  for (int k : s.levels)
    if (k >= 0 && stale_[k] && populated(k)) rebuild_subsets(k);
  use_subsets(kc);
  return s;
}

bool TimeAdaptivity::populated(int k) const {
  if (k < 0) return false;
  for (const auto& list : lists_[k])
    if (!list.empty()) return true;
  return false;
}

void TimeAdaptivity::bring_in_pending(int tick) {
  if (pending_.empty()) return;
  auto due = [&](const Pending& e) { return e.due == tick; };
  for (const Pending& e : pending_) {
    if (!due(e)) continue;
    auto& list = lists_[e.k][e.level];
    list.insert(std::lower_bound(list.begin(), list.end(), e.point), e.point);
    stale_[e.k] = 1;
  }
  std::erase_if(pending_, due);
}

// The ghosts whose force reaches a particle of time level k: a ghost depends on the points of
// its interpolation tet, visited in the ghost update order (method.md §4.8), so one pass marks
// every ghost that depends, directly or through other ghosts, on a marked particle. A fixed
// ghost passes nothing on (its force goes to the support).
void TimeAdaptivity::mark_needed_ghosts(int k) {
  const int L = num_levels();
  for (int l = 0; l < L; ++l) {
    for (int p : lists_[k][l]) reach_[l][p] = 1;
    need_iface_[k][l].clear();
    need_sub_[k][l].clear();
  }
  auto scan = [&](const std::vector<int>& ghosts, int l, int source, const Embedding& emb,
                  std::vector<int>& out) {
    const TetMesh& mesh = *models_[source]->mesh;
    for (int g : ghosts) {
      if (!states_[l].free_point[g]) continue;
      const Tet& t = mesh.tets[emb.tet[g]];
      bool reaches = false;
      for (int a = 0; a < 4; ++a) reaches = reaches || (emb.bary[g][a] != 0 && reach_[source][t[a]]);
      if (!reaches) continue;
      reach_[l][g] = 1;
      out.push_back(g);
    }
  };
  for (int l = L - 2; l >= 0; --l)
    scan(status_.ghost_sub(l), l, l + 1, h_.links(l).child_tet, need_sub_[k][l]);
  for (int l = 1; l < L; ++l)
    scan(status_.ghost_iface(l), l, l - 1, h_.links(l).parent_tet, need_iface_[k][l]);
  for (int l = 0; l < L; ++l) {
    for (int p : lists_[k][l]) reach_[l][p] = 0;
    for (int g : need_iface_[k][l]) reach_[l][g] = 0;
    for (int g : need_sub_[k][l]) reach_[l][g] = 0;
  }
}

void TimeAdaptivity::rebuild_subsets(int k) {
  mark_needed_ghosts(k);
  for (int l = 0; l < num_levels(); ++l) {
    merge_sorted(need_sub_[k][l], need_iface_[k][l], ghosts_scratch_);
    fields_[l]->subset_for(lists_[k][l], ghosts_scratch_, subset_[k][l]);
  }
  stale_[k] = 0;
}

void TimeAdaptivity::use_subsets(int kc) {
  const bool fine = populated(K_), coarse = populated(kc);
  for (int l = 0; l < num_levels(); ++l) {
    if (fine && coarse) {
      merge_subsets(subset_[K_][l], subset_[kc][l], merged_[l]);
      merge_sorted(need_iface_[K_][l], need_iface_[kc][l], merged_iface_[l]);
      merge_sorted(need_sub_[K_][l], need_sub_[kc][l], merged_sub_[l]);
      fields_[l]->use(&merged_[l]);
      selection_.iface[l] = &merged_iface_[l];
      selection_.sub[l] = &merged_sub_[l];
      continue;
    }
    const int k = fine || !coarse ? K_ : kc;
    fields_[l]->use(&subset_[k][l]);
    selection_.iface[l] = &need_iface_[k][l];
    selection_.sub[l] = &need_sub_[k][l];
  }
}

void TimeAdaptivity::release_fields() {
  for (LevelForceField* f : fields_) f->use(nullptr);
}

void TimeAdaptivity::after_step(const SubStep& s, std::vector<TimeLevelChange>& changes) {
  frame_work_.push_back(0);
  for (int k : s.levels) {
    if (k < 0) continue;
    const double dt = rules_.frame_dt / static_cast<double>(1 << k);
    // Past the frame end, a refined particle starts the next frame in phase like every other.
    const int due = k < K_ ? wc_.first_kick_after_refining(k, s.tick) : 0;
    const bool joins_this_frame = due < wc_.ticks_per_frame();
    for (int l = 0; l < num_levels(); ++l) {
      auto& list = lists_[k][l];
      evaluations_[k] += static_cast<std::int64_t>(list.size());
      frame_work_.back() += static_cast<std::int64_t>(list.size());
      const PointState& st = states_[l];
      bool refined = false;
      for (int p : list) {
        const double delta =
            velocity_change(st.f[p], st.inv_mass[p], dt, models_[l]->min_edge[p]);
        if (delta > rules_.velocity_change && k < K_) {
          time_level_[l][p] = static_cast<std::int8_t>(k + 1);
          delta_max_[l][p] = -1.0f;  // not measured on the new level yet
          if (joins_this_frame) pending_.push_back({l, p, k + 1, due});
          changes.push_back({l, p, k, k + 1});
          refined = true;
        } else {
          delta_max_[l][p] = std::max(delta_max_[l][p], static_cast<float>(delta));
        }
      }
      if (!refined) continue;
      std::erase_if(list, [&](int p) { return time_level_[l][p] != k; });
      stale_[k] = 1;
    }
  }
}

void TimeAdaptivity::end_frame(std::vector<TimeLevelChange>& changes) {
  pending_.clear();  // every level's steps end with the frame: all start the next one in phase
  const float calm = static_cast<float>(rules_.velocity_change / 4);
  for (int l = 0; l < num_levels(); ++l)
    for (int p : status_.active(l)) {
      const int k = time_level_[l][p];
      if (k < 0) continue;
      const float d = delta_max_[l][p];
      if (k > stable_level_[l][p] && d >= 0 && d < calm) {
        time_level_[l][p] = static_cast<std::int8_t>(k - 1);
        changes.push_back({l, p, k, k - 1});
      }
      delta_max_[l][p] = -1.0f;
    }
  rebuild_lists();
}

void TimeAdaptivity::restore(std::vector<std::vector<std::int8_t>> time_level,
                             std::vector<std::vector<std::int8_t>> stable_level,
                             std::vector<std::int64_t> evaluations) {
  const auto fits = [&](const std::vector<std::vector<std::int8_t>>& levels, int lowest) {
    if (levels.size() != time_level_.size()) return false;
    for (size_t l = 0; l < levels.size(); ++l) {
      if (levels[l].size() != time_level_[l].size()) return false;
      for (std::int8_t k : levels[l])
        if (k < lowest || k > K_) return false;
    }
    return true;
  };
  if (!fits(time_level, -1) || !fits(stable_level, 0) || evaluations.size() != evaluations_.size())
    throw std::invalid_argument("TimeAdaptivity::restore: time levels of another hierarchy");
  time_level_ = std::move(time_level);
  stable_level_ = std::move(stable_level);
  evaluations_ = std::move(evaluations);
  pending_.clear();
  for (auto& d : delta_max_) std::fill(d.begin(), d.end(), -1.0f);
  rebuild_lists();
}

std::vector<std::int64_t> TimeAdaptivity::particles_per_level() const {
  std::vector<std::int64_t> n(rules_.max_level + 1, 0);
  for (size_t k = 0; k < lists_.size(); ++k)
    for (const auto& list : lists_[k]) n[k] += static_cast<std::int64_t>(list.size());
  for (const Pending& e : pending_) ++n[e.k];
  return n;
}

}  // namespace mrsim
