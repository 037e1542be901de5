#pragma once
// Several independent meshes of one object simulated together (thesis ch. 5, method.md §4):
// each level integrates only its active points, ghosts are refreshed after every position update
// (§4.8), and splits/merges change the active sets between steps. Level 0 alone, never split,
// is exactly the single-level model.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "contact/skin_contact.hpp"
#include "hierarchy/coupling_kind.hpp"
#include "hierarchy/ghost_update.hpp"
#include "hierarchy/interface_inertia.hpp"
#include "hierarchy/level_calibration.hpp"
#include "hierarchy/patch_test_weights.hpp"
#include "hierarchy/status_lists.hpp"
#include "hierarchy/tet_locator.hpp"
#include "io/checkpoint_data.hpp"
#include "physics/level_model.hpp"
#include "simulation/level_force_field.hpp"
#include "simulation/surface_load.hpp"
#include "simulation/time_adaptivity.hpp"
#include "time/stepper.hpp"

namespace mrsim {

struct HierarchySetup {
  MaterialLaw law;
  // Per level, when object.calibration gives the coarser levels their own tensors
  // (hierarchy/level_calibration.hpp); empty: `law` on every level.
  std::vector<MaterialLaw> level_laws;
  std::vector<LevelCalibration> calibration;  // the fit's report, per level (or empty)
  Vec3 gravity = Vec3::Zero();
  Integrator integrator = Integrator::ModifiedEuler;
  Coupling coupling = Coupling::Energy;
  double dt = 1e-3;
  std::vector<std::vector<std::uint8_t>> fixed;  // per level, 1 = Dirichlet; empty = none
  Vec3 initial_velocity = Vec3::Zero();          // m/s, every free point of every level
  Vec3 initial_angular_velocity = Vec3::Zero();  // rad/s about level 0's centre of mass
  std::vector<SurfaceLoad> loads;                // surface loads, nodal forces per level
  int steps_per_frame = 1;                       // steps of dt per advance_frame()
  // Without time levels: when the stable step in force (times `courant`) falls below dt at a
  // frame start, the frame's steps double (and halve back, never below steps_per_frame).
  bool adapt_step = false;
  double courant = 1.0;
  // Per-particle time levels (method.md §5.2, §5.4): each particle steps frame_dt / 2^k and
  // advance_frame() runs the W-cycle; dt and steps_per_frame are then unused.
  std::optional<TimeLevelRules> time_levels;
  // Rigid tools against the skin (method.md §6.2); the skin defaults to the finest level's
  // boundary when `skin` is empty.
  std::vector<Tool> tools;
  std::optional<Skin> skin;
};

class HierarchicalSimulation {
 public:
  /// `models`: the levels' models when the caller built them already (level_models() in
  /// simulation/stable_step.hpp, with the setup's laws and integrator); built here otherwise.
  HierarchicalSimulation(const std::vector<const TetMesh*>& meshes, const HierarchySetup& setup,
                         std::vector<LevelModel> models = {});

  int num_levels() const { return static_cast<int>(models_.size()); }
  const LevelModel& model(int l) const { return *models_[l]; }
  const PointState& state(int l) const { return states_[l]; }
  /// For changing the point state: the caches of it (the skin's positions) are dropped.
  PointState& state(int l) {
    changed();
    return states_[l];
  }
  const Hierarchy& hierarchy() const { return *hierarchy_; }
  /// One point locator per level (static), built when first asked for: for the level links
  /// and the skin binding when the result cache does not hold them (simulation/link_cache.hpp),
  /// and for the frames' level ownership.
  const std::vector<TetLocator>& locators() const;
  /// The calibration fit of each level (empty without object.calibration).
  const std::vector<LevelCalibration>& calibration() const { return calibration_; }
  const StatusLists& lists() const { return *lists_; }
  std::int64_t force_evaluations(int l) const {
    return stepper_->force_evaluations(time_levels_ ? 2 * l : l);
  }

  /// Per-tet stress evaluations of level l's kernels so far (LevelForceField::tet_updates).
  std::int64_t tet_updates(int l) const { return forces_[l]->tet_updates(); }
  /// The tets of level l with an active vertex (sorted), as its force pass keeps them since the
  /// last topology change; nullptr when that pass keeps none (Cauchy without ghosts).
  const std::vector<int>* live_tets(int l) const { return forces_[l]->kept_live_tets(); }

  /// `steps` steps of dt (not with time levels: their unit is the frame).
  void advance(int steps);
  /// One display frame: steps_per_frame steps of dt, or the W-cycle with time levels. Time-
  /// level changes (refinements during the frame, coarsenings at its end) go to `changes`.
  void advance_frame(std::vector<TimeLevelChange>* changes = nullptr);
  /// Part `part` of a display frame cut into `parts` equal parts (without time levels; `parts`
  /// dividing steps_per_frame): part 0 starts the frame as advance_frame() does, and every
  /// later part first shortens the step if the stable step in force needs it (never lengthens
  /// it: the parts stay whole numbers of steps), so that splits made between parts
  /// (adaptivity.space.split_checks) run at their own stable step. One part is advance_frame().
  void advance_frame_part(int part, int parts);
  bool time_levels_enabled() const { return time_levels_ != nullptr; }
  /// Simulated time (s) since the start.
  double time() const { return time_; }
  /// Steps of the next (or current) frame without time levels: the setup's, or more when the
  /// stable step in force needs them (HierarchySetup::adapt_step).
  int steps_per_frame() const { return steps_per_frame_; }
  /// Integration steps taken (with time levels: W-cycle sub-steps that integrated something).
  std::int64_t steps() const { return steps_; }
  /// What the last adjustment of the interface weights achieved (energy coupling).
  const PatchTestReport& patch_test() const { return patch_report_; }
  /// Mass (the one the integrator uses: interface masses under the energy couplings) and the
  /// stiffness and damping energy bounds, without contact, of every active point of level l
  /// (other entries are scratch). Updated at every topology change.
  const std::vector<PointInertia>& inertia(int l) const { return inertia_[l]; }
  /// Largest stable step of every active free point of level l (s; docs/integrators.md), with
  /// the contact the tools may add during the current frame.
  const std::vector<double>& stable_steps(int l) const { return stable_dt_[l]; }
  /// The smallest of them and where: the stable step in force for the current topology.
  struct StableStepInForce {
    double dt = 0;
    int level = -1, point = -1;
  };
  const StableStepInForce& stable_step_in_force() const { return in_force_; }
  /// Step of the particles (s): dt, or with time levels the finest frame_dt / 2^K.
  double step() const;
  /// The per-particle time levels, nullptr when the setup has none.
  const TimeAdaptivity* time_levels() const { return time_levels_.get(); }

  /// The state at a frame boundary, for a checkpoint (simulation/checkpoint_state.cpp).
  SimulationCheckpoint checkpoint() const;
  /// Back to a checkpoint's state, on a simulation freshly built from the same scenario: the
  /// counters and states are taken back, everything derived from the topology is rebuilt by
  /// the code a run uses, so the run goes on bit for bit as if it had never stopped. Throws
  /// std::invalid_argument (or std::runtime_error for a broken hierarchy) when the checkpoint
  /// does not fit this simulation.
  void restore(const SimulationCheckpoint& checkpoint);

  /// Topology changes, applied between steps. After any of them call apply_changes().
  void split(int level, int point);
  void merge(int level, int point);
  int collect_garbage() { return hierarchy_->collect_garbage(); }
  /// Did a split, merge or garbage collection change a status since the last apply_changes()?
  bool changes_pending() const { return hierarchy_->has_touched() || !woken_.empty(); }
  /// Refiles points, gives newly woken points their interpolated state, refreshes ghosts,
  /// force fields and the integrator.
  void apply_changes();

  /// Every inactive point gets the displacement interpolated from the coarser levels (output).
  void fill_inactive();
  /// Ghost refresh (method.md §4.8); also what the stepper calls after position updates.
  void refresh_ghosts();
  /// The ghosts' entries of `fields` (one per level) interpolated from their sources' entries,
  /// exactly as refresh_ghosts() sets u and v (Dirichlet ghosts at zero).
  void interpolate_ghosts(std::vector<LevelFields>& fields) const;
  /// state(l).f of every active point at the current state, exactly as a step computes it
  /// (ghost forces transferred under energy coupling). Not counted as work. For probes/tests.
  void compute_forces();
  Coupling coupling() const { return coupling_; }
  /// Does the integrator filter velocities (eq. 5.1, time/semi_implicit_filter.hpp)?
  bool semi_implicit() const { return semi_implicit_; }
  /// Force that fixed ghosts and fixed loaded points pass to the support instead of to active
  /// points (N), at the last force evaluation / load update: part of the support reaction.
  Vec3 held_by_support() const {
    return ghosts_on_support_ + loads_on_support_ + contact_on_support_;
  }
  /// Σ of the external forces (loads and contacts) on the active points plus the share held by
  /// the support, at the last update (N): where the tools' reactions went.
  Vec3 external_on_body() const;
  /// External force (loads and contacts) on every point of level l at the last update (N);
  /// empty without loads or tools.
  std::span<const Vec3> external_force(int l) const {
    return external_.empty() ? std::span<const Vec3>() : std::span<const Vec3>(external_[l]);
  }
  /// Calls visit(level, point, force) for every point a surface load acts on, with the load
  /// at the last update (N): external_force without the contacts.
  void for_each_surface_load(const std::function<void(int, int, const Vec3&)>& visit) const;
  /// The same with each load at the largest magnitude its profile takes over the next
  /// `horizon` s (surface_load.hpp peak_load_factor): what is about to act.
  void for_each_surface_load_ahead(double horizon,
                                   const std::function<void(int, int, const Vec3&)>& visit) const;
  /// The tools and the skin, nullptr without tools. Samples accumulate over the frames until
  /// the caller clears them.
  const SkinContact* contact() const { return contact_.get(); }
  /// Wall time of internal forces, ghosts and contact so far (core/task_clock.hpp); the run
  /// adds the other tasks.
  TaskClock& task_clock() { return tasks_; }
  SkinContact* contact() { return contact_.get(); }
  /// The active points that move a skin vertex some tool may reach during the next
  /// `lookahead` seconds, as (level, point), sorted, unique: where contact is coming.
  void contact_region(double lookahead, std::vector<std::pair<int, int>>& out) const;
  /// Displacement and velocity of every skin vertex (sized here).
  void skin_state(std::vector<Vec3>& u, std::vector<Vec3>& v) const;

 private:
  Vec3 fresh_value(int l, int q, bool velocity) const;
  Vec3 from_parent(int l, int q, bool velocity) const;
  void resolve_loads();
  void deposit(int load, int l, int p, const Vec3& force,
               const std::vector<const std::vector<std::uint8_t>*>& free,
               std::vector<ActiveTerm>& row);
  void update_external(double t);
  void begin_frame(double duration);
  void run_steps(int steps);
  void adapt_step(bool may_lengthen = true, int parts = 1);
  void remap_skin();
  // Each surface load's targets with its force at the given factor per load.
  void visit_loads(const std::vector<double>& factors,
                   const std::function<void(int, int, const Vec3&)>& visit) const;
  std::vector<const std::vector<std::uint8_t>*> free_points() const;
  void after_positions();
  void transfer_forces();
  void refile_fixed_ghosts();
  void update_inertia();
  void update_stable_steps();
  void refresh_tangent_growths();
  // The stable steps change between topology changes: with the contact near the tools and with
  // Green–Lagrange's growth, refreshed at each frame start.
  bool steps_follow_frames() const { return contact_ || tracks_stiffening_; }
  void restart_integrator();
  void rebuild_after_topology(double external_time);
  void run_w_cycle(std::vector<TimeLevelChange>& changes);
  void drift_all(int from, int to, double frame_start, double tick);

  std::vector<std::unique_ptr<LevelModel>> models_;
  std::vector<LevelCalibration> calibration_;
  std::vector<PointState> states_;
  std::vector<const TetMesh*> meshes_;
  mutable std::vector<TetLocator> locators_;  // empty until locators() is first called
  std::unique_ptr<Hierarchy> hierarchy_;
  std::unique_ptr<StatusLists> lists_;
  std::vector<std::unique_ptr<LevelForceField>> forces_;
  std::vector<std::unique_ptr<SemiImplicitFilter>> filters_;  // per level, semi-implicit only
  std::unique_ptr<Stepper> stepper_;
  std::unique_ptr<TimeAdaptivity> time_levels_;
  std::unique_ptr<PatchTestWeights> patch_;
  PatchTestReport patch_report_;
  void adjust_interface_weights();
  std::vector<TimeLevelChange> changes_scratch_;
  const std::vector<int> nobody_;  // an empty point list for idle blocks
  bool in_sub_step_ = false;       // forces are evaluated for one sub-step's particles only
  int steps_per_frame_ = 1, base_steps_per_frame_ = 1;
  bool adapt_step_ = false;
  double courant_ = 1.0, global_frame_ = 0;  // global_frame_: dt × steps per frame
  std::int64_t frames_ = 0, steps_ = 0;
  // Names the state of the fields: every step, topology change and edit takes a new one, so a
  // value computed from the fields can be kept while it stays (SkinContact::near_tools()).
  std::uint64_t version_ = 1;
  std::uint64_t growths_version_ = 0;  // of stiffness_growth_ and damping_growth_
  void changed() { ++version_; }
  double frame_dt_ = 0;
  std::vector<LevelFields> fields_;
  std::vector<Vec3*> level_forces_;  // f of every level, for the ghost force transfer
  std::vector<std::pair<int, int>> woken_;
  std::vector<std::vector<std::uint8_t>> stale_;  // woken, not yet initialised
  std::vector<std::vector<int>> fixed_;          // Dirichlet points per level
  std::vector<std::vector<int>> fixed_ghosts_;   // those that are ghosts now
  double dt_ = 0;
  double time_ = 0, clock_ = 0;  // clock_: the time positions reach in the step under way
  double external_at_ = 0;       // time of the last update_external (checkpoints)
  std::vector<SurfaceLoad> loads_;
  std::vector<double> load_factors_;  // per load, at the last update (scratch)
  Vec3 ghosts_on_support_ = Vec3::Zero(), loads_on_support_ = Vec3::Zero();
  struct LoadTarget {  // the share of a load an active point (level -1: the support) carries
    int load, level, point;
    Vec3 force;
  };
  std::vector<LoadTarget> load_targets_;  // rebuilt when the active sets change
  std::vector<std::vector<Vec3>> external_;  // per level, Σ factor × nodal load (N)
  std::unique_ptr<SkinContact> contact_;
  std::vector<Vec3*> external_ptrs_;  // external_[l].data()
  Vec3 contact_on_support_ = Vec3::Zero();
  Coupling coupling_ = Coupling::Energy;
  bool transfer_ = false;  // energy coupling with more than one level
  bool semi_implicit_ = false;
  bool global_step_ = true;  // no time levels: stable steps calibrated by each level's spectrum
  // Semi-implicit with a Green–Lagrange level: the stable steps follow the strain
  // (refresh_tangent_growths(); the filter's allowance, or the time levels' bounds).
  bool tracks_stiffening_ = false;
  // [level][point]: g and g_d of the points of the evaluated tets (the largest among each
  // point's tets), refreshed with refresh_tangent_growths().
  std::vector<std::vector<double>> stiffness_growth_, damping_growth_;
  double step_share_ = 1.0;  // of the kick-drift stable step (Newton-Cotes: half)
  TaskClock tasks_;
  std::vector<std::vector<PointInertia>> inertia_;  // [level][point], active points
  MergedRows inertia_rows_;  // interface_inertia()'s scratch, kept between topology changes
  std::vector<std::vector<PointInertia>> loaded_;   // the same with the tools' contact
  std::vector<int> near_;                           // skin vertices near a tool (scratch)
  std::vector<std::vector<double>> stable_dt_;      // [level][point], active free points
  StableStepInForce in_force_;
};

}  // namespace mrsim
