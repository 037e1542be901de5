#include "simulation/run.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cmath>
#include <ctime>
#include <fstream>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>
#include <utility>

#include "core/error.hpp"
#include "core/interruption.hpp"
#include "core/log.hpp"
#include "hierarchy/level_ownership.hpp"
#include "io/checkpoint_file.hpp"
#include "io/hdf5_log.hpp"
#include "io/run_folder.hpp"
#include "io/summary_json.hpp"
#include "core/vtk_module.hpp"
#include "io/frame_series_writer.hpp"
#include "mesh/mesh_reader.hpp"
#include "mrsim/version.hpp"
#include "physics/green_nodal_forces.hpp"
#include "contact/tool_surface.hpp"
#include "simulation/checkpoint_state.hpp"
#include "simulation/contact_setup.hpp"
#include "simulation/mesh_cache.hpp"
#include "simulation/divergence.hpp"
#include "simulation/frame_timing.hpp"
#include "simulation/hierarchy_diagnostics.hpp"
#include "simulation/level_setup_from_scenario.hpp"
#include "simulation/stable_step.hpp"

namespace mrsim {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::vector<TetMesh> load_meshes(const Scenario& sc) {
  std::vector<TetMesh> meshes;
  for (const LevelSpec& level : sc.levels) {
    MeshReadReport report;
    meshes.push_back(read_level_mesh(level.mesh, sc.units, &report));
    for (const std::string& w : report.warnings) warn(w);
  }
  return meshes;
}

// The step of each column of /frames/time_levels (docs/output.md).
std::vector<double> time_level_steps(const Scenario& sc) {
  if (!sc.time_levels.enabled) return {sc.time.frame_dt / sc.time.substeps};
  std::vector<double> steps;
  for (int n = 1; n <= sc.time.substeps; n *= 2) steps.push_back(sc.time.frame_dt / n);
  return steps;
}

// /levels/level_k attributes of a calibrated hierarchy (docs/output.md): the seven factors and
// the level alone against the finest level before and after the fit.
std::vector<std::vector<NamedValues>> calibration_attributes(
    const std::vector<LevelCalibration>& calibration) {
  std::vector<std::vector<NamedValues>> out;
  for (const LevelCalibration& c : calibration) {
    const std::array<double, 7> scales = c.scales.components();
    std::vector<NamedValues> all = {{"calibration_scales", {scales.begin(), scales.end()}}};
    if (!c.tet_tensors.empty()) {  // per_tet: the range (a coarse level may have many tets)
      const std::array<double, 2> range = c.tet_factor_range();
      all.push_back({"calibration_tet_scale_range", {range[0], range[1]}});
    }
    // The finest level (and a free body's sags) have no ratios: only what exists is written.
    for (const CalibrationRatios& r : kCalibrationRatios)
      if (!(c.*r.member).empty())
        all.push_back({std::string("calibration_") + r.quantity + "_ratio_" + r.when, c.*r.member});
    out.push_back(std::move(all));
  }
  return out;
}

std::vector<const TetMesh*> pointers(const std::vector<TetMesh>& meshes) {
  std::vector<const TetMesh*> p;
  for (const TetMesh& m : meshes) p.push_back(&m);
  return p;
}

// Every file a run reads: none of them may be removed with a previous run's outputs.
std::vector<std::filesystem::path> input_files(const Scenario& sc) {
  std::vector<std::filesystem::path> files{sc.source, sc.skin};
  for (const LevelSpec& level : sc.levels) files.push_back(level.mesh);
  for (const ToolSpec& tool : sc.tools) files.push_back(tool.csv);
  return files;
}

int frame_count(const TimeSpec& t) {
  const double exact = t.duration / t.frame_dt;
  const long long frames = std::max(1LL, std::llround(exact));
  if (std::abs(static_cast<double>(frames) - exact) > 1e-9 * exact) {
    std::ostringstream os;
    os << "time.duration " << t.duration << " s is not a multiple of time.frame_dt "
       << t.frame_dt << " s: running " << frames << " frames (" << frames * t.frame_dt << " s)";
    warn(os.str());
  }
  return static_cast<int>(frames);
}

// The frames of the VTK series up to frame `last` (index, time), as the run wrote them.
std::vector<std::pair<int, double>> vtk_frames_up_to(const Scenario& sc, int last) {
  std::vector<std::pair<int, double>> frames;
  for (int f = 0; f <= last; f += sc.output.every) frames.emplace_back(f, f * sc.time.frame_dt);
  return frames;
}

// Everything written per display frame: one block / status row per level. With `resume`, the
// run's outputs are taken up where its checkpoint left them.
class FrameWriter {
 public:
  FrameWriter(const Scenario& sc, HierarchicalSimulation& sim, const SpaceAdaptivity& adapt,
              const Checkpoint* resume)
      : sc_(sc), sim_(sim), adapt_(adapt), L_(sim.num_levels()),
        scenario_text_(resume ? resume->scenario_yaml : resolved_yaml(sc)) {
    status_.resize(L_);
    force_.resize(L_);
    time_level_.resize(L_);
    simulated_.resize(L_);
    simulated_by_.resize(L_);
    std::vector<const TetMesh*> meshes;
    for (int l = 0; l < L_; ++l) {
      status_[l].assign(sim.model(l).num_points(), 0);
      force_[l].assign(sim.model(l).num_points(), Vec3::Zero());
      time_level_[l].assign(sim.model(l).num_points(), 0);
      meshes.push_back(sim.model(l).mesh);
    }
    std::filesystem::create_directories(sc.output.dir);
    if (!resume) write_text(sc.output.dir / "scenario.yaml", scenario_text_);
    Hdf5LogHeader header{kVersion, kGitRevision, scenario_text_, utc_now_iso8601(), meshes,
                         time_level_steps(sc)};
    header.level_attributes = calibration_attributes(sim.calibration());
    if (const SkinContact* c = sim.contact())
      for (int k = 0; k < c->num_tools(); ++k) {
        header.tools.push_back({c->tool(k).name, shape_name(c->tool(k).shape.kind)});
        tool_surfaces_.push_back(tool_surface(c->tool(k).shape));
      }
    if (resume) {
      // The checkpoint's copy of the log, not the folder's: a run killed while it flushed
      // log.h5 may have left it torn (HDF5 files are not crash-consistent).
      restore_checkpoint_log(sc.output.dir / kCheckpointFile, sc.output.dir / "log.h5");
      const RunCheckpoint& r = resume->run;
      log_ = std::make_unique<Hdf5Log>(sc.output.dir / "log.h5", header,
                                       Hdf5LogRows{r.frame + 1, r.log_events, r.log_tool_samples});
      peak_tool_force_ = r.peak_tool_force;
      run_parts_ = r.wall_time_parts;
    } else {
      log_ = std::make_unique<Hdf5Log>(sc.output.dir / "log.h5", header);
    }
    if (sc.output.vtk) {
      vtk_ = vtk_module().series_writer(sc.output.dir, sc.output.compression);
      if (resume) vtk_->resume(vtk_frames_up_to(sc, resume->run.frame), resume->run.frame);
    }
  }

  /// The resolved scenario the run was started with (log.h5, scenario.yaml, checkpoints).
  const std::string& scenario_text() const { return scenario_text_; }
  /// Rows of log.h5 written so far.
  Hdf5LogRows log_rows() const { return log_->rows(); }

  /// The frame's row of log.h5 and, when due, its VTK files. `timing` started with the frame:
  /// the output is timed here and the row gets the frame's wall time per task. The row is
  /// appended after the frame's files.
  void write(int frame, double time, double frame_wall, const Energies& e, FrameTiming& timing) {
    timing.carry(Task::Output, unaccounted_log_write_);
    const auto start = Clock::now();
    const double counted = timing.counted();
    FrameRecord rec;
    rec.frame = frame;
    rec.time = time;
    rec.kinetic_energy = e.kinetic;
    rec.elastic_energy = e.elastic;
    rec.wall_time = frame_wall;
    rec.stable_step = sim_.stable_step_in_force().dt;
    rec.step = sim_.step();
    rec.support_reaction = support_reaction(sim_);
    for (int l = 0; l < L_; ++l) {
      fill_status(l);
      rec.active.push_back(static_cast<std::int64_t>(sim_.lists().active(l).size()));
      rec.ghosts.push_back(static_cast<std::int64_t>(sim_.lists().ghost_sub(l).size() +
                                                     sim_.lists().ghost_iface(l).size()));
      rec.force_evaluations.push_back(sim_.force_evaluations(l));
      rec.tet_updates.push_back(sim_.tet_updates(l));
      rec.status.push_back(std::span<const std::int8_t>(status_[l]));
    }
    if (const TimeAdaptivity* ta = sim_.time_levels()) {
      rec.time_levels = ta->particles_per_level();
      rec.time_level_evaluations = ta->evaluations();
    } else {  // one step for every particle: one column
      std::int64_t integrated = 0, evaluations = 0;
      for (int l = 0; l < L_; ++l) {
        const PointState& s = std::as_const(sim_).state(l);  // read only: keeps its caches
        for (int p : sim_.lists().active(l)) integrated += s.free_point[p];
        evaluations += sim_.force_evaluations(l);
      }
      rec.time_levels = {integrated};
      rec.time_level_evaluations = {evaluations};
    }
    write_tool_samples(rec);
    if (vtk_ && frame % sc_.output.every == 0) write_vtk(frame, time);
    timing.add_phase(Task::Output, start, counted);
    rec.wall_time_parts = timing.finish();
    for (std::size_t k = 0; k < kTaskCount; ++k) run_parts_[k] += rec.wall_time_parts[k];
    // Appending and flushing the row (about 0.4 ms on liver_probe's four levels, as much as
    // its ghosts over a frame) is charged to the next frame's output; run_parts() counts it now.
    const auto append_start = Clock::now();
    log_->append_frame(rec);
    unaccounted_log_write_ = seconds_since(append_start);
  }

  /// Σ over the frames written so far of their wall time per task (s), the last row's append
  /// included (a resumed run starts from this: its first frame carries nothing).
  TaskClock::Parts run_parts() const {
    TaskClock::Parts parts = run_parts_;
    parts[static_cast<std::size_t>(Task::Output)] += unaccounted_log_write_;
    return parts;
  }

  /// Largest force on any tool at any step so far (N).
  double peak_tool_force() const { return peak_tool_force_; }

  void event(const HierarchyEvent& e) { log_->append_event(e.frame, e.kind, e.level, e.point); }
  void close() { log_->close(); }

 private:
  static void write_text(const std::filesystem::path& file, const std::string& text) {
    std::ofstream out(file);
    out << text;
    if (!out) throw RunError("cannot write " + file.string());
  }

  // The haptic-rate samples of the frame (every step), then the buffers start again.
  void write_tool_samples(FrameRecord& rec) {
    SkinContact* c = sim_.contact();
    if (!c) return;
    for (int k = 0; k < c->num_tools(); ++k) {
      const ToolSampleBuffer& b = c->samples(k);
      log_->append_tool_samples(k, {b.time, b.position, b.orientation, b.force, b.contacts});
      for (const Vec3& f : b.force) peak_tool_force_ = std::max(peak_tool_force_, f.norm());
      rec.tool_force.push_back(c->tool_force(k));
    }
    c->clear_samples();
  }

  void fill_status(int l) {
    for (int p = 0; p < sim_.model(l).num_points(); ++p) {
      const NodeState s = sim_.hierarchy().state(l, p);
      status_[l][p] = static_cast<std::int8_t>(
          s == NodeState::Active ? PointStatus::Active
          : s == NodeState::Inactive ? PointStatus::Inactive : PointStatus::Ghost);
    }
  }

  // The column of /frames/time_levels each point steps with, -1 where nothing is integrated.
  void fill_time_levels(int l) {
    std::fill(time_level_[l].begin(), time_level_[l].end(), -1);
    const TimeAdaptivity* ta = sim_.time_levels();
    for (int p : sim_.lists().active(l))
      if (std::as_const(sim_).state(l).free_point[p])
        time_level_[l][p] = ta ? ta->level_of(l, p) : 0;
  }

  // Per tet of level l: the share of it level l simulates (hierarchy/level_ownership.hpp), in
  // the statuses ownership_ last observed.
  void fill_simulated(int l) { ownership_->shares(l, simulated_[l], simulated_by_[l]); }

  void write_vtk(int frame, double time) {
    sim_.fill_inactive();  // every level shows the whole deformed object
    if (!ownership_) ownership_ = std::make_unique<LevelOwnership>(sim_.hierarchy(), sim_.locators());
    // The shares follow the statuses only: recounted after a topology change, else kept.
    const bool coverage_changed = ownership_->observe(sim_.hierarchy());
    std::vector<LevelFrameView> views(L_);
    for (int l = 0; l < L_; ++l) {
      const PointState& s = std::as_const(sim_).state(l);
      fill_time_levels(l);
      std::fill(force_[l].begin(), force_[l].end(), Vec3::Zero());
      for (int p : sim_.lists().active(l)) force_[l][p] = s.f[p];  // only active points have one
      LevelFrameView& v = views[l];
      v.mesh = sim_.model(l).mesh;
      v.displacement = s.u;
      v.velocity = s.v;
      v.force = force_[l];
      v.status = status_[l];
      v.time_level = time_level_[l];
      v.criterion = adapt_.criterion(l);
      v.mass = sim_.model(l).mass;
      if (coverage_changed) fill_simulated(l);
      v.simulated = simulated_[l];
      v.simulated_by = simulated_by_[l];
      if (const auto& tensors = sim_.model(l).law.tet_tensors) v.calibration_scale = *tensors;
    }
    if (const SkinContact* c = sim_.contact()) {
      sim_.skin_state(skin_u_, skin_v_);
      skin_level_.resize(skin_u_.size());
      for (std::size_t s = 0; s < skin_level_.size(); ++s)
        skin_level_[s] = static_cast<std::int8_t>(c->map().level(static_cast<int>(s)));
      const SurfaceFrameView surface{c->skin().rest, c->skin().triangles, skin_u_, skin_v_,
                                     c->vertex_force(), skin_level_};
      std::vector<ToolFrameView> tools;
      tool_points_.resize(c->num_tools());
      for (int k = 0; k < c->num_tools(); ++k) {
        const ToolPose pose = c->tool(k).trajectory.pose(time);
        tool_points_[k].clear();
        for (const Vec3& p : tool_surfaces_[k].points) tool_points_[k].push_back(pose.to_world(p));
        tools.push_back({tool_points_[k], tool_surfaces_[k].triangles, c->tool_force(k)});
      }
      vtk_->write_frame(frame, time, views, &surface, tools);
      return;
    }
    vtk_->write_frame(frame, time, views);
  }

  const Scenario& sc_;
  HierarchicalSimulation& sim_;
  const SpaceAdaptivity& adapt_;
  int L_;
  std::string scenario_text_;
  std::vector<std::vector<std::int8_t>> status_;
  std::vector<std::vector<Vec3>> force_;
  std::vector<std::vector<std::int32_t>> time_level_;
  std::vector<std::vector<double>> simulated_;         // per tet (fill_simulated)
  std::vector<std::vector<std::int8_t>> simulated_by_;  // per tet (fill_simulated)
  std::unique_ptr<LevelOwnership> ownership_;   // built at the first VTK frame
  std::unique_ptr<Hdf5Log> log_;
  std::unique_ptr<FrameSeriesWriter> vtk_;  // io/vtk_series_writer.hpp
  TaskClock::Parts run_parts_{};
  double unaccounted_log_write_ = 0;  // s: the last row's append, not yet in any frame's parts
  std::vector<TriangleSurface> tool_surfaces_;  // per tool, in the tool frame
  std::vector<std::vector<Vec3>> tool_points_;  // per tool, posed (scratch)
  std::vector<Vec3> skin_u_, skin_v_;
  std::vector<std::int8_t> skin_level_;
  double peak_tool_force_ = 0;
};

struct RunState {
  int frames_done = 0;
  double max_displacement = 0;
  Energies energies;
  std::string status = "completed";
  std::string message;
  std::int64_t splits = 0, merges = 0;
  std::int64_t budget_hold = 0, budget_shed = 0;  // frames over the real-time budget
  int substep_changes = 0;                         // time.adapt_substeps
};

RunState run_state_of(const RunCheckpoint& r) {
  RunState st;
  st.frames_done = r.frame;
  st.max_displacement = r.max_displacement;
  st.splits = r.splits;
  st.merges = r.merges;
  st.budget_hold = r.budget_hold;
  st.budget_shed = r.budget_shed;
  st.substep_changes = r.substep_changes;
  return st;
}

// checkpoint.h5 at the end of the frame just written (docs/output.md "Checkpoints").
void save_checkpoint(const Scenario& sc, const HierarchicalSimulation& sim,
                     const SpaceAdaptivity& adapt, const FrameWriter& writer, const RunState& st,
                     int frames, double wall_time) {
  Checkpoint c;
  c.mrsim_version = kVersion;
  c.git_revision = kGitRevision;
  c.scenario_yaml = writer.scenario_text();
  c.scenario_source = std::filesystem::absolute(sc.source).lexically_normal().string();
  RunCheckpoint& r = c.run;
  r.frame = st.frames_done;
  r.frames_total = frames;
  r.max_displacement = st.max_displacement;
  r.splits = st.splits;
  r.merges = st.merges;
  r.budget_hold = st.budget_hold;
  r.budget_shed = st.budget_shed;
  r.substep_changes = st.substep_changes;
  r.peak_tool_force = writer.peak_tool_force();
  r.wall_time = wall_time;
  r.wall_time_parts = writer.run_parts();
  const Hdf5LogRows rows = writer.log_rows();
  r.log_events = rows.events;
  r.log_tool_samples = rows.tool_samples;
  c.simulation = take_checkpoint(sim, adapt);
  write_checkpoint(sc.output.dir / kCheckpointFile, c, sc.output.dir / "log.h5");
}

// The splits and merges of a frame boundary: logged and counted for summary.json.
void record_events(const std::vector<HierarchyEvent>& events, FrameWriter& writer, RunState& st) {
  for (const HierarchyEvent& e : events) {
    st.splits += e.kind == "split";
    st.merges += e.kind == "merge";
    writer.event(e);
  }
}

// time.adapt_substeps: the frame just run took another number of steps than the one before,
// because the stable step in force changed (docs/integrators.md). An event per change; a line
// on stderr for the first few.
void report_substeps(const HierarchicalSimulation& sim, int frame, int before,
                     FrameWriter& writer, RunState& st) {
  const auto& where = sim.stable_step_in_force();
  writer.event({frame, "substeps", where.level, where.point});
  if (++st.substep_changes > 5) return;
  std::ostringstream os;
  os.precision(4);
  os << "frame " << frame << ": " << sim.steps_per_frame() << " substeps instead of " << before
     << " (stable step estimate in force " << where.dt << " s at point " << where.point
     << " of level " << where.level << ")" << (st.substep_changes == 5 ? "; further changes "
     "are only logged (events 'substeps')" : "");
  info(os.str());
}

// method.md §6.2 point 5: the rule for the adaptivity at a frame boundary from the wall time
// the frame's simulation took. Free unless adaptivity.budget.realtime.
BudgetRule budget_rule(const Scenario& sc, double last_simulation_wall) {
  if (!sc.budget.realtime) return BudgetRule::Free;
  if (last_simulation_wall > sc.time.frame_dt) return BudgetRule::Shed;
  if (last_simulation_wall > sc.budget.fraction * sc.time.frame_dt) return BudgetRule::HoldSplits;
  return BudgetRule::Free;
}

// One display frame. With adaptivity.space.split_checks = n > 1 (one global step) the frame
// runs in n equal parts and the criterion may split after each of the first n - 1 (merges wait
// for the frame's end): a sudden load refines within the frame that bends the object. Not after
// a frame over its real-time budget. The splits go to `events`.
void simulate_frame(HierarchicalSimulation& sim, SpaceAdaptivity& adapt, int frame, int checks,
                    bool hold_splits, std::vector<TimeLevelChange>& changes, FrameTiming& timing,
                    std::vector<HierarchyEvent>& events) {
  events.clear();
  const int parts = std::min(checks, sim.steps_per_frame());  // both powers of two
  if (parts <= 1 || sim.time_levels_enabled()) {
    timing.phase(Task::Integration, [&] { sim.advance_frame(&changes); });
    return;
  }
  for (int part = 0; part < parts; ++part) {
    timing.phase(Task::Integration, [&] { sim.advance_frame_part(part, parts); });
    if (part + 1 < parts && !hold_splits)
      timing.phase(Task::Adaptivity, [&] { adapt.split_within_frame(sim, frame, events); });
  }
}

nlohmann::json summary_json(const Scenario& sc, const HierarchicalSimulation& sim,
                            const RunState& st, const RunSummary& sum, double peak_tool_force,
                            const TaskClock::Parts& parts) {
  nlohmann::json j;
  j["name"] = sc.name;
  j["status"] = st.status;
  j["message"] = st.message;
  j["mrsim_version"] = kVersion;
  j["git_revision"] = kGitRevision;
  j["force_kernel"] = green_kernel_name();
  j["frames"] = st.frames_done;
  j["simulated_time"] = sum.simulated_time;
  j["steps"] = sum.steps;
  j["wall_time"] = sum.wall_time;
  // Simulated seconds per wall second, set-up included: what a real-time user checks first.
  j["real_time_factor"] = real_time_factor(sum);
  // The frames' wall time per task and its shares (docs/output.md), as the thesis reports them.
  const double frames_wall = std::accumulate(parts.begin(), parts.end(), 0.0);
  for (std::size_t k = 0; k < kTaskCount; ++k) {
    j["wall_time_parts"][kTaskNames[k]] = parts[k];
    j["wall_time_shares"][kTaskNames[k]] = frames_wall > 0 ? parts[k] / frames_wall : 0.0;
  }
  j["splits"] = st.splits;
  j["merges"] = st.merges;
  if (sc.budget.realtime) {
    j["budget_hold_frames"] = st.budget_hold;
    j["budget_shed_frames"] = st.budget_shed;
  }
  for (int l = 0; l < sim.num_levels(); ++l) {
    j["force_evaluations"].push_back(sim.force_evaluations(l));
    j["tet_updates"].push_back(sim.tet_updates(l));
    j["final_active"].push_back(sim.lists().active(l).size());
    j["final_ghosts"].push_back(sim.lists().ghost_sub(l).size() + sim.lists().ghost_iface(l).size());
    j["points"].push_back(sim.model(l).num_points());
    j["tets"].push_back(sim.model(l).num_tets());
  }
  if (const TimeAdaptivity* ta = sim.time_levels()) {
    j["time_level_evaluations"] = ta->evaluations();
    j["final_time_levels"] = ta->particles_per_level();
  }
  j["max_displacement"] = st.max_displacement;
  if (sim.contact())
    j["peak_tool_force"] = peak_tool_force;
  else
    j["peak_tool_force"] = nullptr;
  j["final_kinetic_energy"] = st.energies.kinetic;
  j["final_elastic_energy"] = st.energies.elastic;
  return j;
}

// sum gets the frames done and the wall time so far; summary.json says how the run ended.
void write_summary(const Scenario& sc, const HierarchicalSimulation& sim, const RunState& st,
                   Clock::time_point t0, double peak_tool_force, const TaskClock::Parts& parts,
                   RunSummary& sum) {
  sum.frames = st.frames_done;
  sum.simulated_time = st.frames_done * sc.time.frame_dt;
  sum.wall_time = seconds_since(t0);
  write_json_file(sc.output.dir / "summary.json",
                  summary_json(sc, sim, st, sum, peak_tool_force, parts));
}

}  // namespace

namespace {

// The skin the tools touch (none without tools), read once for the stable step and the run.
std::optional<Skin> run_skin(const Scenario& sc, const std::vector<TetMesh>& meshes) {
  if (sc.tools.empty()) return std::nullopt;
  return scenario_skin(sc, meshes.back());
}

}  // namespace

Scenario check_scenario_inputs(const Scenario& sc) {
  const std::vector<TetMesh> meshes = load_meshes(sc);
  // Fixed regions and loads select something; tool trajectories and the skin read.
  const LevelLaws laws = level_laws(sc, pointers(meshes));
  const std::optional<Skin> skin = run_skin(sc, meshes);
  hierarchy_setup(sc, pointers(meshes), &laws, skin ? &*skin : nullptr);
  return with_stable_substeps(sc, pointers(meshes), &laws, nullptr, skin ? &*skin : nullptr);
}

namespace {

// A run from its start (resume == nullptr) or from a checkpoint of it.
RunSummary execute(const Scenario& input, const RunOptions& options, const Checkpoint* resume) {
  const double wall_before = resume ? resume->run.wall_time : 0.0;
  const auto t0 = Clock::now() - std::chrono::duration_cast<Clock::duration>(
                                     std::chrono::duration<double>(wall_before));
  const std::vector<TetMesh> meshes = load_meshes(input);
  const LevelLaws laws = level_laws(input, pointers(meshes));
  // Built once: the computed substeps and the simulation read the same models.
  std::vector<LevelModel> models = level_models(input, pointers(meshes), laws);
  // Built once too: the skin the computed substeps and the tools read.
  const std::optional<Skin> skin = run_skin(input, meshes);
  const Skin* skin_ptr = skin ? &*skin : nullptr;
  const Scenario sc = with_stable_substeps(input, pointers(meshes), &laws, &models, skin_ptr);
  const HierarchySetup setup = hierarchy_setup(sc, pointers(meshes), &laws, skin_ptr);
  HierarchicalSimulation sim(pointers(meshes), setup, std::move(models));
  SpaceAdaptivity adapt(space_settings(sc), sim);
  const DivergenceGuard guard =
      DivergenceGuard::for_level(sim.model(0), sc.time.divergence_energy_factor);
  const int frames = frame_count(sc.time);
  if (resume) {
    try {
      restore_checkpoint(resume->simulation, sim, adapt);
    } catch (const std::exception& e) {
      throw InputError((sc.output.dir / kCheckpointFile).string() +
                       " does not fit the run's scenario and meshes: " + e.what());
    }
  }

  // The folder is this run's from here on: locked, the previous run's outputs removed (or,
  // resuming, taken up where the checkpoint left them).
  RunFolder folder(sc.output.dir, input_files(sc),
                   resume ? RunFolder::Mode::Resume : RunFolder::Mode::Fresh);
  RunState st = resume ? run_state_of(resume->run) : RunState{};
  RunSummary sum;
  sum.steps = sim.steps();
  try {
    FrameWriter writer(sc, sim, adapt, resume);
    folder.remember("log.h5");  // open for the whole run: its removal would go unnoticed
    std::vector<HierarchyEvent> events;
    std::vector<TimeLevelChange> changes;
    st.energies = hierarchy_energies(sim);
    FrameTiming timing(sim.task_clock());  // frame 0: its output only
    if (!resume) {
      if (sc.space.predict) {
        // A first split decision at t = 0 on the displacement the loads are about to cause.
        timing.phase(Task::Adaptivity, [&] { adapt.update(sim, 0, events, BudgetRule::Free); });
        record_events(events, writer, st);
        events.clear();
        st.energies = hierarchy_energies(sim);
      } else {
        adapt.evaluate(sim);
      }
      writer.write(0, 0.0, 0.0, st.energies, timing);
    }
    bool hold_splits = false;  // the last frame was over its real-time budget
    for (int frame = st.frames_done + 1; frame <= frames; ++frame) {
      timing.restart();
      const auto tf = timing.start();
      changes.clear();
      const int substeps = sim.steps_per_frame();
      simulate_frame(sim, adapt, frame, sc.space.split_checks, hold_splits, changes, timing,
                     events);
      record_events(events, writer, st);
      if (sim.steps_per_frame() != substeps) report_substeps(sim, frame, substeps, writer, st);
      // The frame just simulated decides whether the hierarchy may grow at its boundary.
      const BudgetRule budget = budget_rule(sc, seconds_since(tf));
      hold_splits = budget != BudgetRule::Free;
      sum.steps = sim.steps();
      const double time = frame * sc.time.frame_dt;
      st.energies = hierarchy_energies(sim);
      if (auto why = guard.check(sim, st.energies.elastic + st.energies.internal_kinetic)) {
        std::ostringstream os;
        os << "simulation diverged at frame " << frame << " (t = " << time << " s): " << *why;
        st.status = "diverged";
        st.message = os.str();
        writer.event({frame, "divergence", -1, -1});
        writer.close();
        write_summary(sc, sim, st, t0, writer.peak_tool_force(), writer.run_parts(), sum);
        throw RunError(st.message);
      }
      for (const TimeLevelChange& c : changes)
        writer.event({frame, c.to > c.from ? "time_refine" : "time_coarsen", c.level, c.point});
      // Split/merge at the frame boundary (method.md §3.3): the frame written shows the new state.
      events.clear();
      if (budget != BudgetRule::Free) {
        writer.event({frame, budget == BudgetRule::Shed ? "budget_shed" : "budget_hold", -1, -1});
        ++(budget == BudgetRule::Shed ? st.budget_shed : st.budget_hold);
      }
      timing.phase(Task::Adaptivity, [&] { adapt.update(sim, frame, events, budget); });
      record_events(events, writer, st);
      st.max_displacement = std::max(st.max_displacement, max_active_displacement(sim));
      folder.check_intact();
      writer.write(frame, time, seconds_since(tf), st.energies, timing);
      st.frames_done = frame;
      const int sig = interruption_signal();
      // A checkpoint at the interruption, or every checkpoint_every frames (none at the end).
      if (frame < frames &&
          (sig != 0 || (sc.output.checkpoint_every > 0 && frame % sc.output.checkpoint_every == 0)))
        save_checkpoint(sc, sim, adapt, writer, st, frames, seconds_since(t0));
      if (options.progress) options.progress({frame, frames, time, seconds_since(t0)});
      if (sig != 0 && frame < frames) {
        // core/interruption.hpp: the frame is written; stop here, cleanly.
        std::ostringstream os;
        os << "interrupted by " << (sig == SIGINT ? "SIGINT" : "SIGTERM") << " after frame "
           << frame << " (t = " << time << " s) of " << frames << "; go on with mrsim run --resume "
           << sc.output.dir.string();
        st.status = "interrupted";
        st.message = os.str();
        writer.event({frame, "interrupted", -1, -1});
        sum.interrupted_by = sig;
        break;
      }
    }
    writer.close();
    write_summary(sc, sim, st, t0, writer.peak_tool_force(), writer.run_parts(), sum);
    return sum;
  } catch (const RunError& e) {
    // An I/O failure (disk full, folder removed): summary.json still says what happened, when
    // it can be written. A divergence has written its own.
    if (st.status == "completed") {
      st.status = "failed";
      st.message = e.what();
      try {
        write_summary(sc, sim, st, t0, std::nan(""), TaskClock::Parts{}, sum);
      } catch (const std::exception&) {  // the disk is full: the error above is what counts
      }
    }
    throw;
  }
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  if (!in) throw InputError("cannot read " + file.string());
  return ss.str();
}

// The 1-based line where two texts first differ.
int first_different_line(const std::string& a, const std::string& b) {
  const auto [ia, ib] = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
  return 1 + static_cast<int>(std::count(a.begin(), ia, '\n'));
}

// What `mrsim run --resume DIR` goes on with: the folder's scenario and its checkpoint, checked
// to belong together, to this build and to a run that has something left to do.
std::pair<Scenario, Checkpoint> resumable_run(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  const std::string where = dir.string();
  if (!fs::is_directory(dir)) throw InputError(where + ": no such run folder to resume");
  const fs::path yaml = dir / "scenario.yaml";
  if (!fs::is_regular_file(yaml))
    throw InputError(where + " holds no run to resume (no scenario.yaml)");
  if (fs::is_regular_file(dir / "summary.json")) {
    nlohmann::json summary;
    try {
      summary = nlohmann::json::parse(read_text(dir / "summary.json"));
    } catch (const nlohmann::json::exception&) {  // torn by a crash: the checkpoint decides
    }
    if (summary.is_object() && summary.value("status", "") == "completed")
      throw InputError("the run in " + where + " completed (summary.json): nothing to resume");
  }
  Checkpoint c = read_checkpoint(dir / kCheckpointFile);
  if (c.mrsim_version != kVersion || c.git_revision != kGitRevision)
    throw InputError((dir / kCheckpointFile).string() + " was written by mrsim " +
                     c.mrsim_version + " (" + c.git_revision + "); this is mrsim " + kVersion +
                     " (" + kGitRevision + "): a run goes on exactly only with the build that "
                     "started it; resume it with that build or run it again");
  const std::string text = read_text(yaml);
  if (text != c.scenario_yaml)
    throw InputError((dir / kCheckpointFile).string() + " belongs to another scenario than " +
                     yaml.string() + " (they differ from line " +
                     std::to_string(first_different_line(text, c.scenario_yaml)) + ")");
  // Read as the file it came from, so that its relative mesh paths mean what they meant.
  Scenario sc = load_scenario_text(text, c.scenario_source, {"output.dir=" + where});
  if (c.run.frame >= frame_count(sc.time))
    throw InputError("the checkpoint in " + where + " is at the run's last frame: nothing to "
                     "resume");
  return {std::move(sc), std::move(c)};
}

}  // namespace

RunSummary run_scenario(const Scenario& input, const RunOptions& options) {
  return execute(input, options, nullptr);
}

RunSummary resume_run(const std::filesystem::path& dir, const RunOptions& options) {
  const auto [sc, checkpoint] = resumable_run(dir);
  return execute(sc, options, &checkpoint);
}

}  // namespace mrsim
