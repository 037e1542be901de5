#include "simulation/hierarchical_simulation.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "contact/skin_binding.hpp"
#include "hierarchy/active_row.hpp"
#include "hierarchy/ghost_force_transfer.hpp"
#include "physics/tangent_growth.hpp"
#include "simulation/diagnostics.hpp"
#include "simulation/link_cache.hpp"
#include "time/explicit_updates.hpp"
#include "time/steps_per_frame.hpp"

namespace mrsim {

namespace {

const std::vector<std::uint8_t> kNoneHeld;

// Was the model built with these held points (its spectra are over the others)?
bool holds(const LevelModel& m, const std::vector<std::uint8_t>& held) {
  for (int i = 0; i < m.num_points(); ++i)
    if (is_held(m, i) != (!held.empty() && held[i] != 0)) return false;
  return true;
}

}  // namespace

HierarchicalSimulation::HierarchicalSimulation(const std::vector<const TetMesh*>& meshes,
                                               const HierarchySetup& setup,
                                               std::vector<LevelModel> models) {
  const int L = static_cast<int>(meshes.size());
  coupling_ = setup.coupling;
  // One level: no ghost, nothing to send.
  transfer_ = (coupling_ == Coupling::Energy || coupling_ == Coupling::EnergyConsistent) && L > 1;
  std::vector<HierarchyLevel> levels;
  calibration_ = setup.calibration;
  for (int l = 0; l < L; ++l) {
    const MaterialLaw& law = setup.level_laws.empty() ? setup.law : setup.level_laws[l];
    const std::vector<std::uint8_t>& held =
        l < static_cast<int>(setup.fixed.size()) ? setup.fixed[l] : kNoneHeld;
    if (static_cast<int>(models.size()) == L && models[l].mesh == meshes[l] &&
        holds(models[l], held))
      models_.push_back(std::make_unique<LevelModel>(std::move(models[l])));
    else
      models_.push_back(std::make_unique<LevelModel>(
          build_level_model(*meshes[l], law, is_semi_implicit(setup.integrator), held)));
    if (setup.time_levels && is_semi_implicit(setup.integrator))
      prepare_semi_implicit_time_levels(*models_[l]);
    levels.push_back({meshes[l], &models_[l]->adj});
  }
  // The links and the skin binding are the hierarchy's geometry: kept between runs.
  meshes_ = meshes;
  const InputHash geometry = hierarchy_inputs(levels);
  const LocatorSource locate = [this]() -> const std::vector<TetLocator>& { return locators(); };
  hierarchy_ =
      std::make_unique<Hierarchy>(levels, cached_level_links(levels, geometry, locate));
  lists_ = std::make_unique<StatusLists>(*hierarchy_);
  states_.resize(L);
  fixed_.resize(L);
  fixed_ghosts_.resize(L);
  stale_.resize(L);
  // With time levels each level has two blocks: the W-cycle integrates two time levels per
  // sub-step (method.md §5.4); the first block evaluates the level's forces for both.
  const int per_level = setup.time_levels ? 2 : 1;
  std::vector<IntegrationBlock> blocks(L * per_level);
  for (int l = 0; l < L; ++l) {
    PointState& s = states_[l];
    s.resize(models_[l]->num_points());
    for (int i = 0; i < s.size(); ++i) s.inv_mass[i] = 1.0 / models_[l]->mass[i];
    if (l < static_cast<int>(setup.fixed.size()) && !setup.fixed[l].empty())
      for (int i = 0; i < s.size(); ++i) s.free_point[i] = setup.fixed[l][i] ? 0 : 1;
    stale_[l].assign(s.size(), 0);
    for (int i = 0; i < s.size(); ++i)
      if (!s.free_point[i]) fixed_[l].push_back(i);
    const Vec3 c = centre_of_mass(*models_[0]->mesh, models_[0]->mass);
    for (int i = 0; i < s.size(); ++i)
      if (s.free_point[i])
        s.v[i] =
            setup.initial_velocity + setup.initial_angular_velocity.cross(meshes[l]->points[i] - c);
    forces_.push_back(std::make_unique<LevelForceField>(*models_[l], setup.gravity));
    if (transfer_)
      forces_[l]->couple(hierarchy_.get(), lists_.get(), l);
    else
      forces_[l]->serve(&lists_->active(l));
    if (is_semi_implicit(setup.integrator))
      filters_.push_back(std::make_unique<SemiImplicitFilter>(*models_[l]));
    for (int b = 0; b < per_level; ++b) {
      IntegrationBlock& block = blocks[l * per_level + b];
      block.state = &s;
      block.forces = b == 0 ? forces_[l].get() : nullptr;
      block.points = setup.time_levels ? &nobody_ : &lists_->active(l);
      block.filter = filters_.empty() ? nullptr : filters_.back().get();
      block.rest = meshes[l]->points.data();
    }
    fields_.push_back({s.u.data(), s.v.data()});
    level_forces_.push_back(s.f.data());
  }
  std::function<void()> gathered;
  if (transfer_) gathered = [this] { transfer_forces(); };
  loads_ = setup.loads;
  load_factors_.assign(loads_.size(), 0.0);
  if (!setup.tools.empty()) {
    Skin skin = setup.skin ? *setup.skin : boundary_skin(*meshes.back());
    SkinBinding binding = cached_skin_binding(
        skin, levels, geometry, L >= 2 ? &hierarchy_->links(L - 1).parent_tet : nullptr, locate);
    contact_ = std::make_unique<SkinContact>(std::move(skin), std::move(binding), setup.tools,
                                             setup.law.lambda + 2.0 * setup.law.mu);
  }
  if (!loads_.empty() || contact_) {
    external_.resize(L);
    for (int l = 0; l < L; ++l) {
      external_[l].assign(models_[l]->num_points(), Vec3::Zero());
      forces_[l]->set_external(external_[l].data());
      external_ptrs_.push_back(external_[l].data());
    }
    resolve_loads();
    remap_skin();
    update_external(0.0);
  }
  semi_implicit_ = is_semi_implicit(setup.integrator);
  global_step_ = !setup.time_levels;
  tracks_stiffening_ = std::any_of(models_.begin(), models_.end(),
                                   [](const auto& m) { return stiffens(*m); });
  step_share_ = is_two_step(setup.integrator) ? kTwoStepMidpointShare : 1.0;
  update_inertia();
  stepper_ = std::make_unique<Stepper>(
      setup.integrator, std::move(blocks), [this] { after_positions(); }, std::move(gathered));
  stepper_->set_clock(&tasks_);
  dt_ = setup.dt;
  steps_per_frame_ = base_steps_per_frame_ = setup.steps_per_frame;
  global_frame_ = setup.dt * setup.steps_per_frame;
  adapt_step_ = setup.adapt_step;
  courant_ = setup.courant;
  if (transfer_ && coupling_ == Coupling::EnergyConsistent)
    patch_ = std::make_unique<PatchTestWeights>(*hierarchy_);
  if (setup.time_levels) {
    frame_dt_ = setup.time_levels->frame_dt;
    std::vector<const LevelModel*> models;
    std::vector<LevelForceField*> fields;
    for (int l = 0; l < L; ++l) {
      models.push_back(models_[l].get());
      fields.push_back(forces_[l].get());
    }
    time_levels_ = std::make_unique<TimeAdaptivity>(*hierarchy_, *lists_, models, fields, states_,
                                                    stable_dt_, *setup.time_levels);
    std::vector<IntegrationBlock> body(L);
    for (int l = 0; l < L; ++l) {
      body[l].state = &states_[l];
      body[l].points = &lists_->active(l);
      body[l].rest = meshes[l]->points.data();
    }
    stepper_->restore_momentum_over(std::move(body));
  }
  restart_integrator();
}

const std::vector<TetLocator>& HierarchicalSimulation::locators() const {
  if (locators_.empty()) {
    locators_.reserve(meshes_.size());
    for (const TetMesh* mesh : meshes_) locators_.emplace_back(*mesh);
  }
  return locators_;
}

// After the point sets changed: Störmer–Verlet needs the force at the current state. With time
// levels every integrator takes kick-drift steps (no saved half-kick force); one evaluation of
// every served point gives the outputs their forces at the frame's time.
void HierarchicalSimulation::restart_integrator() {  // forces only: the fields' version stays
  if (time_levels_)
    compute_forces();
  else
    stepper_->start();
}

void HierarchicalSimulation::advance_frame(std::vector<TimeLevelChange>* changes) {
  if (!time_levels_) {
    begin_frame(steps_per_frame_ * dt_);
    adapt_step();
    run_steps(steps_per_frame_);
    return;
  }
  std::vector<TimeLevelChange>& out = changes ? *changes : changes_scratch_;
  changes_scratch_.clear();
  begin_frame(frame_dt_);
  if (steps_follow_frames()) time_levels_->restable();
  run_w_cycle(out);
  ++frames_;
  time_ = static_cast<double>(frames_) * frame_dt_;
  time_levels_->end_frame(out);
  // Every particle is at the end of the frame: one full evaluation (not counted as work)
  // gives the outputs their forces and support reaction at one common time.
  compute_forces();
}

void HierarchicalSimulation::advance_frame_part(int part, int parts) {
  if (time_levels_)
    throw std::logic_error("HierarchicalSimulation::advance_frame_part: not with time levels");
  if (part == 0) begin_frame(steps_per_frame_ * dt_);
  // Within the frame the step only shortens, and every part stays a whole number of steps.
  adapt_step(part == 0, parts);
  if (parts < 1 || steps_per_frame_ % parts != 0)
    throw std::logic_error("HierarchicalSimulation::advance_frame_part: " +
                           std::to_string(steps_per_frame_) + " steps in " +
                           std::to_string(parts) + " parts");
  run_steps(steps_per_frame_ / parts);
}

// method.md §5.4 (time/w_cycle.hpp): at each tick that kicks somebody, every particle first
// drifts to that tick and the ghosts follow, then the particles of (at most) two time levels get
// their forces and kicks. With every particle on the finest level this is exactly the global
// step (kick, drift, ghost refresh).
void HierarchicalSimulation::run_w_cycle(std::vector<TimeLevelChange>& changes) {
  TimeAdaptivity& ta = *time_levels_;
  const WCycle& wc = ta.schedule();
  const double tick = frame_dt_ / wc.ticks_per_frame();
  const double frame_start = time_;
  int drifted = 0;  // tick the positions are at
  // Ticks between two tool samples: the largest power of two within the haptic period.
  int haptic = 1;
  while (2 * haptic * tick <= kHapticPeriod * (1 + 1e-12) && 2 * haptic <= wc.ticks_per_frame())
    haptic *= 2;
  ta.begin_frame();
  in_sub_step_ = true;
  while (!ta.frame_done()) {
    const TimeAdaptivity::SubStep s = ta.next();
    bool any = false;
    for (int l = 0; l < num_levels(); ++l)
      for (int b = 0; b < 2; ++b) {
        IntegrationBlock& block = stepper_->block(2 * l + b);
        const int k = s.levels[b];
        block.points = k >= 0 ? &ta.kicked(k, l) : &nobody_;
        block.dt_scale = k >= 0 ? wc.period(k) : 1.0;
        any = any || !block.points->empty();
      }
    if (!any) {
      if (contact_ && s.tick > 0 && s.tick % haptic == 0) {  // nobody kicked: skin sampled
        drift_all(drifted, s.tick, frame_start, tick);
        drifted = s.tick;
        contact_->record_sample();
      }
      continue;
    }
    drift_all(drifted, s.tick, frame_start, tick);
    drifted = s.tick;
    // Samples cover (frame start, frame end], as without time levels: tick 0 is the previous
    // frame's end, sampled there (or t = 0, which a step never samples either).
    if (contact_ && s.tick > 0) contact_->record_sample();
    stepper_->kick_step(tick);
    ++steps_;
    changed();
    ta.after_step(s, changes);
  }
  drift_all(drifted, wc.ticks_per_frame(), frame_start, tick);
  if (contact_) contact_->record_sample();  // the frame's end: the last run's last sample
  in_sub_step_ = false;
  ta.release_fields();
}

// Every active particle moves on from tick `from` to tick `to` with its current velocity; the
// ghosts and the loads follow (what the stepper's sync does after its drifts).
void HierarchicalSimulation::drift_all(int from, int to, double frame_start, double tick) {
  if (to == from) return;
  const double dt = (to - from) * tick;
  for (int l = 0; l < num_levels(); ++l) drift(states_[l], IndexSet::of(lists_->active(l)), dt);
  clock_ = frame_start + to * tick;
  after_positions();
}

void HierarchicalSimulation::advance(int steps) {
  if (time_levels_)
    throw std::logic_error("HierarchicalSimulation::advance: with time levels use advance_frame");
  begin_frame(steps * dt_);
  run_steps(steps);
}

// The frame's step follows the stable step in force (without time levels). When the step
// exceeds it, the frame takes the fewest steps that fit it with kStepHeadroom to spare, so that
// the next small dip of the estimate changes nothing; at frame starts (`may_lengthen`) it takes
// fewer again as soon as fewer fit that way, never fewer than the setup's. Doubling instead, as
// until 2026-12-02, cost up to twice the steps needed once the computed steps were the fewest
// that fit (docs/integrators.md "The stable step"); 10 % to spare, and fewer steps only once a
// tenth fewer fit, kept some runs up to 9 % above the doubling.
void HierarchicalSimulation::adapt_step(bool may_lengthen, int parts) {
  if (!adapt_step_) return;
  constexpr double kStepHeadroom = 1.05;
  const double allowed = courant_ * in_force_.dt;
  const auto fit = [&] {
    return std::max<long long>(
        base_steps_per_frame_,
        fewest_steps(global_frame_, allowed / kStepHeadroom, parts, kMaxSubsteps));
  };
  long long steps = steps_per_frame_;
  if (dt_ > allowed)
    steps = std::max(steps, fit());
  else if (may_lengthen && steps > base_steps_per_frame_)
    steps = std::min(steps, fit());
  if (steps == steps_per_frame_) return;
  steps_per_frame_ = static_cast<int>(steps);
  dt_ = global_frame_ / steps_per_frame_;
}

void HierarchicalSimulation::run_steps(int steps) {
  for (int s = 0; s < steps; ++s) {
    clock_ = time_ + dt_;
    stepper_->step(dt_);
    time_ = clock_;
    ++steps_;
    changed();
    if (contact_) contact_->record_sample();
  }
}

// The broad phase over the coming frame, then the contact forces again from its candidates
// (the first step must see every vertex that already touches a tool); then the stable steps in
// force, which follow the skin near the tools and Green–Lagrange's growth
// (refresh_tangent_growths()).
void HierarchicalSimulation::begin_frame(double duration) {
  if (contact_) {
    {
      const TaskTimer timer(&tasks_, Task::Contact);
      contact_->begin_frame(time_, time_ + duration, fields_, version_);
    }
    update_external(time_);
  }
  if (steps_follow_frames()) update_stable_steps();
}

void HierarchicalSimulation::remap_skin() {
  if (!contact_) return;
  contact_->remap(*hierarchy_, free_points());
}

std::vector<const std::vector<std::uint8_t>*> HierarchicalSimulation::free_points() const {
  std::vector<const std::vector<std::uint8_t>*> free(num_levels());
  for (int l = 0; l < num_levels(); ++l) free[l] = &states_[l].free_point;
  return free;
}

void HierarchicalSimulation::contact_region(double lookahead,
                                            std::vector<std::pair<int, int>>& out) const {
  out.clear();
  if (!contact_) return;
  std::vector<std::vector<int>> near;
  contact_->near_tools(time_, time_ + lookahead, fields_, near, version_);
  for (const std::vector<int>& vertices : near)
    for (int s : vertices)
      for (const ActiveTerm& t : contact_->map().row(s))
        if (t.level >= 0) out.emplace_back(t.level, t.point);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

Vec3 HierarchicalSimulation::external_on_body() const {
  Vec3 sum = loads_on_support_ + contact_on_support_;
  if (external_.empty()) return sum;
  for (int l = 0; l < num_levels(); ++l)
    for (int p : lists_->active(l)) sum += external_[l][p];
  return sum;
}

void HierarchicalSimulation::skin_state(std::vector<Vec3>& u, std::vector<Vec3>& v) const {
  const int n = contact_ ? contact_->map().size() : 0;
  u.resize(n);
  v.resize(n);
  for (int s = 0; s < n; ++s) {
    contact_->map().interpolate(s, fields_, u[s], v[s]);
  }
}

// Positions (and with them the load time) moved to the end of the step under way.
void HierarchicalSimulation::after_positions() {  // refresh_ghosts() names the new state
  refresh_ghosts();
  if (!external_.empty()) update_external(clock_);
}

// A force on point p of level l reaches the active points that move p, with the weights that
// move it (hierarchy/active_row.hpp; level -1: held by the support).
void HierarchicalSimulation::deposit(int load, int l, int p, const Vec3& force,
                                     const std::vector<const std::vector<std::uint8_t>*>& free,
                                     std::vector<ActiveTerm>& row) {
  row.clear();
  append_active_row(*hierarchy_, free, l, p, 1.0, row);
  for (const ActiveTerm& t : row)
    load_targets_.push_back({load, t.level, t.point, t.weight * force});
}

// Once per topology change: where every nodal load lands, merged per (load, level, point).
void HierarchicalSimulation::resolve_loads() {
  for (const LoadTarget& target : load_targets_)
    if (target.level >= 0) external_[target.level][target.point].setZero();
  load_targets_.clear();
  const int fine = num_levels() - 1;
  const auto free = free_points();
  std::vector<ActiveTerm> row;
  for (int k = 0; k < static_cast<int>(loads_.size()); ++k)
    for (size_t i = 0; i < loads_[k].finest.points.size(); ++i)
      deposit(k, fine, loads_[k].finest.points[i], loads_[k].finest.force[i], free, row);
  auto key = [](const LoadTarget& a) { return std::tuple(a.load, a.level, a.point); };
  std::stable_sort(load_targets_.begin(), load_targets_.end(),
                   [&](const LoadTarget& a, const LoadTarget& b) { return key(a) < key(b); });
  std::vector<LoadTarget> merged;
  for (const LoadTarget& t : load_targets_) {
    if (!merged.empty() && key(merged.back()) == key(t))
      merged.back().force += t.force;
    else
      merged.push_back(t);
  }
  load_targets_ = std::move(merged);
}

// O(loaded points + contact candidates) per step: clear the previous shares of the loads and
// the contacts (they may share points), then add each load at its factor and the contacts.
void HierarchicalSimulation::update_external(double t) {
  const TaskTimer timer(&tasks_, Task::Contact);
  external_at_ = t;
  loads_on_support_.setZero();
  for (size_t k = 0; k < loads_.size(); ++k) load_factors_[k] = load_factor(loads_[k].profile, t);
  for (const LoadTarget& target : load_targets_)
    if (target.level >= 0) external_[target.level][target.point].setZero();
  if (contact_) {
    contact_->clear(external_ptrs_);
    contact_on_support_ = contact_->apply(t, fields_, external_ptrs_);
  }
  for (const LoadTarget& target : load_targets_) {
    const Vec3 f = load_factors_[target.load] * target.force;
    if (target.level >= 0)
      external_[target.level][target.point] += f;
    else
      loads_on_support_ += f;
  }
}

void HierarchicalSimulation::for_each_surface_load(
    const std::function<void(int, int, const Vec3&)>& visit) const {
  visit_loads(load_factors_, visit);
}

void HierarchicalSimulation::for_each_surface_load_ahead(
    double horizon, const std::function<void(int, int, const Vec3&)>& visit) const {
  std::vector<double> ahead(loads_.size());
  for (std::size_t k = 0; k < loads_.size(); ++k)
    ahead[k] = peak_load_factor(loads_[k].profile, time_, time_ + horizon);
  visit_loads(ahead, visit);
}

void HierarchicalSimulation::visit_loads(
    const std::vector<double>& factors,
    const std::function<void(int, int, const Vec3&)>& visit) const {
  for (const LoadTarget& target : load_targets_)
    if (target.level >= 0) visit(target.level, target.point, factors[target.load] * target.force);
}

// A Dirichlet point stays at rest on every level, ghost or not: its row of the interpolation
// map is zero, so it never carries a stale interpolated value into a split (a prestress) and
// its force goes to the support, not to its sources.
void HierarchicalSimulation::refresh_ghosts() {
  changed();
  const TaskTimer timer(&tasks_, Task::Ghosts);
  interpolate_ghosts(fields_);
}

void HierarchicalSimulation::interpolate_ghosts(std::vector<LevelFields>& fields) const {
  update_ghosts(*hierarchy_, *lists_, fields);
  for (int l = 0; l < num_levels(); ++l)
    for (int p : fixed_ghosts_[l]) {
      fields[l].u[p].setZero();
      fields[l].v[p].setZero();
    }
}

void HierarchicalSimulation::transfer_forces() {
  const TaskTimer timer(&tasks_, Task::Ghosts);
  ghosts_on_support_.setZero();
  for (int l = 0; l < num_levels(); ++l)
    for (int p : fixed_ghosts_[l]) {
      ghosts_on_support_ += states_[l].f[p];
      states_[l].f[p].setZero();
    }
  if (in_sub_step_)
    transfer_ghost_forces(*hierarchy_, time_levels_->ghosts(), level_forces_);
  else
    transfer_ghost_forces(*hierarchy_, *lists_, level_forces_);
}

// O(fixed points), once per topology change.
void HierarchicalSimulation::refile_fixed_ghosts() {
  for (int l = 0; l < num_levels(); ++l) {
    fixed_ghosts_[l].clear();
    for (int p : fixed_[l]) {
      const NodeState s = hierarchy_->state(l, p);
      if (s == NodeState::GhostSub || s == NodeState::GhostIface) fixed_ghosts_[l].push_back(p);
    }
  }
}

void HierarchicalSimulation::compute_forces() {
  {
    const TaskTimer timer(&tasks_, Task::InternalForces);
    for (int l = 0; l < num_levels(); ++l)
      forces_[l]->evaluate(states_[l].u.data(), states_[l].v.data(), states_[l].f.data());
  }
  if (transfer_) transfer_forces();
}

void HierarchicalSimulation::split(int level, int point) {
  for (const auto& w : hierarchy_->split(level, point)) {
    woken_.push_back(w);
    stale_[w.first][w.second] = 1;
  }
}

void HierarchicalSimulation::merge(int level, int point) { hierarchy_->merge(level, point); }

// The current value of a point that may not be simulated: its own if it is up to date,
// otherwise interpolated from its parent tet, recursively (level 0 is always up to date).
Vec3 HierarchicalSimulation::fresh_value(int l, int q, bool velocity) const {
  const bool own = l == 0 || (!stale_[l][q] && hierarchy_->state(l, q) != NodeState::Inactive);
  if (own) return velocity ? states_[l].v[q] : states_[l].u[q];
  return from_parent(l, q, velocity);
}

Vec3 HierarchicalSimulation::from_parent(int l, int q, bool velocity) const {
  const auto& emb = hierarchy_->links(l).parent_tet;
  const Tet& t = models_[l - 1]->mesh->tets[emb.tet[q]];
  Vec3 x = Vec3::Zero();
  for (int a = 0; a < 4; ++a) x += emb.bary[q][a] * fresh_value(l - 1, t[a], velocity);
  return x;
}

void HierarchicalSimulation::apply_changes() {
  lists_->update(*hierarchy_, hierarchy_->take_touched());
  // Coarse to fine, so a woken point's sources are initialised before it.
  std::sort(woken_.begin(), woken_.end());
  for (const auto& [l, q] : woken_) {
    if (!stale_[l][q]) continue;
    stale_[l][q] = 0;
    if (!states_[l].free_point[q]) {  // Dirichlet points stay at rest (u may hold a display value)
      states_[l].u[q].setZero();
      states_[l].v[q].setZero();
      continue;
    }
    // From its parent tet (never its own value: it is stale). A woken point is never on level 0.
    states_[l].u[q] = from_parent(l, q, false);
    states_[l].v[q] = from_parent(l, q, true);
  }
  woken_.clear();
  rebuild_after_topology(time_);
  restart_integrator();
}

// Everything that follows from the statuses, once the lists are refiled and the points' values
// are current: after a split or merge (apply_changes) and when a checkpoint is taken back.
void HierarchicalSimulation::rebuild_after_topology(double external_time) {
  changed();
  refile_fixed_ghosts();
  for (auto& f : forces_) f->refresh_tets();
  adjust_interface_weights();
  refresh_ghosts();
  if (!external_.empty()) {
    resolve_loads();
    remap_skin();
    update_external(external_time);
  }
  update_inertia();
  if (time_levels_) time_levels_->refile();
}

// Once per topology change, after the weights and the skin map: the masses the integrator
// uses and gravity follow the tets' shares (hierarchy/interface_inertia.hpp).
void HierarchicalSimulation::update_inertia() {
  const int L = num_levels();
  std::vector<InertiaLevel> levels(L);
  for (int l = 0; l < L; ++l) {
    levels[l].model = models_[l].get();
    levels[l].free_point = &states_[l].free_point;
    if (transfer_ && forces_[l]->weighted()) {
      levels[l].tets = &forces_[l]->tets();
      levels[l].weight = &forces_[l]->tet_weights();
    }
  }
  interface_inertia(*hierarchy_, *lists_, levels, transfer_, inertia_, inertia_rows_);
  for (int l = 0; l < L; ++l) {
    forces_[l]->weigh(lists_->active(l), inertia_[l]);
    for (int p : lists_->active(l))
      if (states_[l].free_point[p]) states_[l].inv_mass[p] = 1.0 / inertia_[l][p].mass;
  }
  update_stable_steps();
}

// After every topology change and at the start of every frame (the skin vertices near the
// tools change): every active point's stable step from what reaches it, its star, ghosts and
// the contact of the vertices a tool may touch in the frame (docs/integrators.md, "The stable
// step"). O(active + contact candidates).
void HierarchicalSimulation::update_stable_steps() {
  const int L = num_levels();
  loaded_.resize(L);
  stable_dt_.resize(L);
  for (int l = 0; l < L; ++l) {
    loaded_[l].resize(models_[l]->num_points());
    stable_dt_[l].resize(models_[l]->num_points(), 0.0);
  }
  // One global step: each level's bounds calibrated by its spectrum (LevelModel calibrated());
  // time levels keep the proven stiffness bounds, the damping calibrated. Both follow
  // Green–Lagrange's growth, each point its own (refresh_tangent_growths()): semi-implicit
  // all of it, explicit what the spectral margin does not cover (explicit_stiffening()).
  if (tracks_stiffening_) refresh_tangent_growths();
  for (int l = 0; l < L; ++l)
    for (int p : lists_->active(l))
      loaded_[l][p] = calibrated(inertia_[l][p], *models_[l], semi_implicit_, !global_step_,
                                 tracks_stiffening_ ? stiffness_growth_[l][p] : 0.0,
                                 tracks_stiffening_ ? damping_growth_[l][p] : 0.0, p);
  if (contact_) {
    near_.clear();
    for (const std::vector<int>& c : contact_->candidates())
      near_.insert(near_.end(), c.begin(), c.end());
    std::sort(near_.begin(), near_.end());
    near_.erase(std::unique(near_.begin(), near_.end()), near_.end());
    const SkinMap& map = contact_->map();
    add_contact_bounds(
        contact_->penalty(), near_,
        [&](int s, std::vector<ActiveTerm>& row) {
          const std::span<const ActiveTerm> r = map.row(s);
          row.insert(row.end(), r.begin(), r.end());
        },
        loaded_);
  }
  in_force_ = {};
  in_force_.dt = std::numeric_limits<double>::infinity();
  for (int l = 0; l < L; ++l)
    for (int p : lists_->active(l)) {
      if (!states_[l].free_point[p]) continue;
      const double dt = stable_step_of(loaded_[l][p], semi_implicit_) * step_share_;
      stable_dt_[l][p] = dt;
      if (dt < in_force_.dt) in_force_ = {dt, l, p};
    }
}

// The semi-implicit filter's blocks are taken at rest, so Green–Lagrange stiffening lands on
// what it leaves explicit: each point's tangent growth g, the largest among its tets the level
// evaluates, at each frame start and topology change (physics/tangent_growth.hpp), sets its
// allowance (spectral_bound.hpp filter_stiffening(), time_level_stiffening()). Per point, as
// the star bound it scales: a point whose tets do not stretch is not held to the growth under
// a tool elsewhere on its level (until 2026-12-02 each level's largest g stood for all its
// points; docs/integrators.md). Not extrapolated with the velocities: just after a split the
// woken points' interpolated velocities made g a frame ahead 12.7 on the little man (0.9 now).
// From the state alone, so a resumed run takes the same steps. Called only when tracked
// (tracks_stiffening_). The damping grows with the strain too, provably by 1 + g_d
// (tangent_growth.hpp), and where ψ is large it is what the filter leaves explicit: each
// point's own g_d scales its damping bound. Without it the 125k-tet liver hierarchy ran 6 %
// beyond its true limit (docs/stability_matrix.md). The explicit schemes take the part of both
// growths that their spectral margin does not cover (a soft beam hanging under gravity reached
// g ≈ 8 and diverged at its computed step when they did not).
void HierarchicalSimulation::refresh_tangent_growths() {
  // From the displacements and the live tets only: a topology change's refresh serves the next
  // frame's start when no step comes between them.
  if (growths_version_ == version_) return;
  growths_version_ = version_;
  stiffness_growth_.resize(num_levels());
  damping_growth_.resize(num_levels());
  for (int l = 0; l < num_levels(); ++l) {
    const LevelModel& m = *models_[l];
    stiffness_growth_[l].resize(m.num_points(), 0.0);
    damping_growth_[l].resize(m.num_points(), 0.0);
    if (stiffens(m))
      tangent_growths_of(m.geo, forces_[l]->tets(), states_[l].u, m.law, stiffness_growth_[l],
                         damping_growth_[l],
                         semi_implicit_ ? GrowthsNeeded{} : explicit_growths_needed());
  }
}

double HierarchicalSimulation::step() const {
  return time_levels_ ? frame_dt_ / time_levels_->schedule().ticks_per_frame() : dt_;
}

// Once per topology change, after the shares: the interface band's weights for the patch test.
void HierarchicalSimulation::adjust_interface_weights() {
  if (!patch_) return;
  std::vector<PatchTestLevel> levels(num_levels());
  for (int l = 0; l < num_levels(); ++l) {
    levels[l].model = models_[l].get();
    levels[l].free_point = &states_[l].free_point;
    levels[l].live_tets = &forces_[l]->tets();
    if (forces_[l]->weighted()) levels[l].weight = &forces_[l]->edit_tet_weights();
  }
  patch_report_ = patch_->apply(levels);
}

void HierarchicalSimulation::fill_inactive() {
  changed();
  interpolate_inactive(*hierarchy_, fields_);
}

}  // namespace mrsim
