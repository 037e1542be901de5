#include "simulation/run.hpp"

#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <memory>
#include <sstream>

#include "core/error.hpp"
#include "core/log.hpp"
#include "io/hdf5_log.hpp"
#include "io/summary_json.hpp"
#include "io/vtk_series_writer.hpp"
#include "mesh/mesh_reader.hpp"
#include "mrsim/version.hpp"
#include "physics/laplacian_criterion.hpp"
#include "simulation/diagnostics.hpp"
#include "simulation/divergence.hpp"
#include "simulation/level_setup_from_scenario.hpp"

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

TetMesh load_level_mesh(const Scenario& sc, size_t level) {
  MeshReadReport report;
  TetMesh mesh = read_tet_mesh(sc.levels[level].mesh, sc.units, &report);
  for (const std::string& w : report.warnings) warn(w);
  return mesh;
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

void warn_if_unstable(const LevelSimulation& sim, Integrator integrator) {
  const double limit = recommended_max_dt(sim.model(), integrator);
  if (sim.dt() > limit) {
    std::ostringstream os;
    os << "time step " << sim.dt() << " s (frame_dt / substeps) exceeds the stable estimate "
       << limit << " s of this mesh (0.5 x shortest edge / P-wave speed"
       << (integrator == Integrator::SemiImplicit ? ", x2 for semi_implicit" : "")
       << "); raise time.substeps to at least " << std::ceil(sim.dt() / limit) << "x its value";
    warn(os.str());
  }
}

// Everything written per display frame for the single level of issue 2.
class FrameWriter {
 public:
  FrameWriter(const Scenario& sc, const LevelSimulation& sim)
      : sc_(sc), sim_(sim), n_(sim.model().num_points()) {
    status_.assign(n_, static_cast<std::int8_t>(PointStatus::Active));
    time_level_.assign(n_, 0);
    std::filesystem::create_directories(sc.output.dir);
    write_text(sc.output.dir / "scenario.yaml", resolved_yaml(sc));
    Hdf5LogHeader header{kVersion, kGitRevision, resolved_yaml(sc), utc_now_iso8601(),
                         {sim.model().mesh}};
    log_ = std::make_unique<Hdf5Log>(sc.output.dir / "log.h5", header);
    if (sc.output.vtk) vtk_ = std::make_unique<VtkSeriesWriter>(sc.output.dir);
  }

  void write(int frame, double time, double frame_wall, double kinetic, double elastic) {
    FrameRecord rec;
    rec.frame = frame;
    rec.time = time;
    rec.kinetic_energy = kinetic;
    rec.elastic_energy = elastic;
    rec.wall_time = frame_wall;
    rec.active = {n_};
    rec.ghosts = {0};
    rec.force_evaluations = {sim_.force_evaluations()};
    rec.status = {std::span<const std::int8_t>(status_)};
    log_->append_frame(rec);
    if (vtk_ && frame % sc_.output.every == 0) write_vtk(frame, time);
  }

  void event(int frame, const std::string& kind) { log_->append_event(frame, kind, 0, -1); }
  void close() { log_->close(); }

 private:
  static void write_text(const std::filesystem::path& file, const std::string& text) {
    std::ofstream out(file);
    out << text;
    if (!out) throw RunError("cannot write " + file.string());
  }

  void write_vtk(int frame, double time) {
    laplacian_criterion(sim_.model(), sim_.state().u.data(), criterion_);
    const PointState& s = sim_.state();
    LevelFrameView view;
    view.mesh = sim_.model().mesh;
    view.displacement = s.u;
    view.velocity = s.v;
    view.force = s.f;
    view.status = status_;
    view.time_level = time_level_;
    view.criterion = criterion_;
    view.mass = sim_.model().mass;
    vtk_->write_frame(frame, time, std::span<const LevelFrameView>(&view, 1));
  }

  const Scenario& sc_;
  const LevelSimulation& sim_;
  std::int64_t n_;
  std::vector<std::int8_t> status_;
  std::vector<std::int32_t> time_level_;
  std::vector<double> criterion_;
  std::unique_ptr<Hdf5Log> log_;
  std::unique_ptr<VtkSeriesWriter> vtk_;
};

struct RunState {
  int frames_done = 0;
  double max_displacement = 0;
  double kinetic = 0, elastic = 0;
  std::string status = "completed";
  std::string message;
};

nlohmann::json summary_json(const Scenario& sc, const LevelSimulation& sim, const RunState& st,
                            const RunSummary& sum) {
  nlohmann::json j;
  j["name"] = sc.name;
  j["status"] = st.status;
  j["message"] = st.message;
  j["mrsim_version"] = kVersion;
  j["git_revision"] = kGitRevision;
  j["frames"] = st.frames_done;
  j["simulated_time"] = st.frames_done * sc.time.frame_dt;
  j["steps"] = sum.steps;
  j["wall_time"] = sum.wall_time;
  j["force_evaluations"] = {sim.force_evaluations()};
  j["final_active"] = {sim.model().num_points()};
  j["final_ghosts"] = {0};
  j["max_displacement"] = st.max_displacement;
  j["peak_tool_force"] = nullptr;  // no tool before issue 6
  j["final_kinetic_energy"] = st.kinetic;
  j["final_elastic_energy"] = st.elastic;
  j["points"] = {sim.model().num_points()};
  j["tets"] = {sim.model().num_tets()};
  return j;
}

}  // namespace

void check_scenario_inputs(const Scenario& sc) {
  for (size_t l = 0; l < sc.levels.size(); ++l) {
    const TetMesh mesh = load_level_mesh(sc, l);
    const LevelSetup setup = level_setup(sc, mesh);
    const LevelModel model = build_level_model(mesh, setup.law);
    const double limit = recommended_max_dt(model, setup.integrator);
    if (setup.dt > limit) {
      std::ostringstream os;
      os << "level " << l << ": time step " << setup.dt << " s exceeds the stable estimate "
         << limit << " s";
      warn(os.str());
    }
  }
}

RunSummary run_scenario(const Scenario& sc, const RunOptions& options) {
  const auto t0 = Clock::now();
  const TetMesh mesh = load_level_mesh(sc, 0);  // issue 2: one level
  LevelSimulation sim(mesh, level_setup(sc, mesh));
  warn_if_unstable(sim, sc.time.integrator);
  const DivergenceGuard guard =
      DivergenceGuard::for_level(sim.model(), sc.time.divergence_energy_factor);
  const int frames = frame_count(sc.time);

  FrameWriter writer(sc, sim);
  RunState st;
  RunSummary sum;
  st.kinetic = kinetic_energy(sim.state(), sim.model().mass);
  st.elastic = sim.elastic_energy();
  writer.write(0, 0.0, 0.0, st.kinetic, st.elastic);
  for (int frame = 1; frame <= frames; ++frame) {
    const auto tf = Clock::now();
    sim.advance(sc.time.substeps);
    sum.steps += sc.time.substeps;
    const double time = frame * sc.time.frame_dt;
    st.kinetic = kinetic_energy(sim.state(), sim.model().mass);
    st.elastic = sim.elastic_energy();
    const double internal = st.elastic + internal_kinetic_energy(sim.state(), sim.model().mass);
    if (auto why = guard.check(sim.state(), internal)) {
      std::ostringstream os;
      os << "simulation diverged at frame " << frame << " (t = " << time << " s): " << *why;
      st.status = "diverged";
      st.message = os.str();
      writer.event(frame, "divergence");
      writer.close();
      sum.frames = st.frames_done;
      sum.wall_time = seconds_since(t0);
      write_json_file(sc.output.dir / "summary.json", summary_json(sc, sim, st, sum));
      throw RunError(st.message);
    }
    st.max_displacement = std::max(st.max_displacement, max_displacement(sim.state()));
    writer.write(frame, time, seconds_since(tf), st.kinetic, st.elastic);
    st.frames_done = frame;
    if (options.progress) options.progress({frame, frames, time, seconds_since(t0)});
  }
  writer.close();
  sum.frames = st.frames_done;
  sum.wall_time = seconds_since(t0);
  write_json_file(sc.output.dir / "summary.json", summary_json(sc, sim, st, sum));
  return sum;
}

}  // namespace mrsim
