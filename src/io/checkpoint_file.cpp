#include "io/checkpoint_file.hpp"

#include <system_error>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/embedded_file.hpp"
#include "io/hdf5_attributes.hpp"
#include "io/hdf5_group.hpp"
#include "io/hdf5_read.hpp"
#include "io/hdf5_static_dataset.hpp"

namespace mrsim {

namespace {

constexpr const char* kFormat = "mrsim checkpoint";
constexpr const char* kLogDataset = "log_h5";

// Writes the datasets of one group; every array is 1-D, or [n, 3] for vectors.
class GroupWriter {
 public:
  GroupWriter(hid_t parent, const std::string& name, const std::string& file)
      : file_(file), path_(name), group_(h5::create_group(parent, name, where())) {}

  template <class T>
  void values(const char* name, const std::vector<T>& v) {
    h5::write_static_dataset<T>(group_.get(), name, std::span<const T>(v), {v.size()}, "", where());
  }
  template <class T>
  void scalar(const char* name, T value) {
    values<T>(name, std::vector<T>{value});
  }
  void bytes(const char* name, const std::vector<std::uint8_t>& v) {
    values<std::int8_t>(name, std::vector<std::int8_t>(v.begin(), v.end()));
  }
  void vectors(const char* name, const std::vector<Vec3>& v) {
    std::vector<double> xyz;
    xyz.reserve(3 * v.size());
    for (const Vec3& p : v) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    h5::write_static_dataset<double>(group_.get(), name, std::span<const double>(xyz),
                                     {v.size(), 3}, "", where());
  }
  hid_t id() const { return group_.get(); }
  void close() { h5::check(group_.close(), where(), "close group"); }

 private:
  h5::Where where() const { return {file_, path_}; }
  std::string file_, path_;
  h5::Handle group_;
};

class GroupReader {
 public:
  GroupReader(hid_t parent, const std::string& name, const std::string& file)
      : file_(file),
        path_(name),
        group_(h5::checked(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose, where(),
                           "open group")) {}

  template <class T>
  std::vector<T> values(const char* name, hsize_t n) {
    return h5::read_dataset<T>(group_.get(), name, {n}, where());
  }
  template <class T>
  std::vector<T> values(const char* name) {
    return values<T>(name, length(name));
  }
  template <class T>
  T scalar(const char* name) {
    return values<T>(name, 1)[0];
  }
  std::vector<std::uint8_t> bytes(const char* name, hsize_t n) {
    const std::vector<std::int8_t> v = values<std::int8_t>(name, n);
    return {v.begin(), v.end()};
  }
  // Vectors of n points, or none (an array the integrator does not use).
  std::vector<Vec3> vectors(const char* name, hsize_t n, bool may_be_empty = false) {
    const std::vector<hsize_t> dims = h5::dataset_dims(group_.get(), name, where());
    if (may_be_empty && dims == std::vector<hsize_t>{0, 3}) return {};
    const std::vector<double> xyz = h5::read_dataset<double>(group_.get(), name, {n, 3}, where());
    std::vector<Vec3> v(n);
    for (hsize_t i = 0; i < n; ++i) v[i] = Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    return v;
  }
  hsize_t length(const char* name) {
    const std::vector<hsize_t> dims = h5::dataset_dims(group_.get(), name, where());
    if (dims.size() != 1) h5::throw_error(where(), std::string("read ") + name + " (not 1-D)");
    return dims[0];
  }
  bool has(const std::string& name) { return h5::has_link(group_.get(), name, where()); }

 private:
  h5::Where where() const { return {file_, path_}; }
  std::string file_, path_;
  h5::Handle group_;
};

void write_run(hid_t file_id, const RunCheckpoint& r, const std::string& file) {
  GroupWriter g(file_id, "run", file);
  g.scalar<std::int32_t>("frame", r.frame);
  g.scalar<std::int32_t>("frames_total", r.frames_total);
  g.scalar<double>("max_displacement", r.max_displacement);
  g.values<std::int64_t>("counters",
                         {r.splits, r.merges, r.budget_hold, r.budget_shed, r.substep_changes});
  g.scalar<double>("peak_tool_force", r.peak_tool_force);
  g.scalar<double>("wall_time", r.wall_time);
  g.values<double>("wall_time_parts", {r.wall_time_parts.begin(), r.wall_time_parts.end()});
  g.scalar<std::int64_t>("log_events", r.log_events);
  g.values<std::int64_t>("log_tool_samples", r.log_tool_samples);
  g.close();
}

RunCheckpoint read_run(hid_t file_id, const std::string& file) {
  GroupReader g(file_id, "run", file);
  RunCheckpoint r;
  r.frame = g.scalar<std::int32_t>("frame");
  r.frames_total = g.scalar<std::int32_t>("frames_total");
  r.max_displacement = g.scalar<double>("max_displacement");
  const std::vector<std::int64_t> c = g.values<std::int64_t>("counters", 5);
  r.splits = c[0];
  r.merges = c[1];
  r.budget_hold = c[2];
  r.budget_shed = c[3];
  r.substep_changes = static_cast<std::int32_t>(c[4]);
  r.peak_tool_force = g.scalar<double>("peak_tool_force");
  r.wall_time = g.scalar<double>("wall_time");
  const std::vector<double> parts = g.values<double>("wall_time_parts", kTaskCount);
  std::copy(parts.begin(), parts.end(), r.wall_time_parts.begin());
  r.log_events = g.scalar<std::int64_t>("log_events");
  r.log_tool_samples = g.values<std::int64_t>("log_tool_samples");
  return r;
}

void write_level(hid_t parent, int l, const LevelCheckpoint& c, const std::string& file) {
  GroupWriter g(parent, "level_" + std::to_string(l), file);
  g.vectors("u", c.u);
  g.vectors("v", c.v);
  g.vectors("f", c.f);
  g.vectors("f_kick", c.f_kick);
  g.vectors("u_prev", c.u_prev);
  g.vectors("v_prev", c.v_prev);
  g.bytes("subdivided", c.subdivided);
  g.bytes("support", c.support);
  g.values<std::int32_t>("active_ref", c.active_ref);
  g.values<std::int32_t>("ghost_ref", c.ghost_ref);
  g.values<std::int32_t>("split_frame", c.split_frame);
  g.values<std::int32_t>("calm_streak", c.calm_streak);
  g.values<std::int8_t>("time_level", c.time_level);
  g.values<std::int8_t>("stable_level", c.stable_level);
  g.close();
}

LevelCheckpoint read_level(hid_t parent, int l, const std::string& file) {
  GroupReader g(parent, "level_" + std::to_string(l), file);
  LevelCheckpoint c;
  const hsize_t n = g.length("active_ref");
  c.u = g.vectors("u", n);
  c.v = g.vectors("v", n);
  c.f = g.vectors("f", n);
  c.f_kick = g.vectors("f_kick", n, true);
  c.u_prev = g.vectors("u_prev", n, true);
  c.v_prev = g.vectors("v_prev", n, true);
  c.subdivided = g.bytes("subdivided", n);
  c.support = g.bytes("support", n);
  c.active_ref = g.values<std::int32_t>("active_ref", n);
  c.ghost_ref = g.values<std::int32_t>("ghost_ref", n);
  c.split_frame = g.values<std::int32_t>("split_frame", n);
  c.calm_streak = g.values<std::int32_t>("calm_streak", n);
  const bool time_levels = g.length("time_level") > 0;
  c.time_level = g.values<std::int8_t>("time_level", time_levels ? n : 0);
  c.stable_level = g.values<std::int8_t>("stable_level", time_levels ? n : 0);
  return c;
}

void write_simulation(hid_t file_id, const SimulationCheckpoint& s, const std::string& file) {
  GroupWriter g(file_id, "simulation", file);
  g.values<double>("times", {s.time, s.clock, s.external_at, s.dt, s.previous_dt});
  g.values<std::int64_t>("counters", {s.frames, s.steps, s.steps_per_frame});
  g.values<std::int64_t>("block_evaluations", s.block_evaluations);
  g.values<std::int64_t>("tet_updates", s.tet_updates);
  g.values<std::int64_t>("time_level_evaluations", s.time_level_evaluations);
  {
    GroupWriter contact(g.id(), "contact_candidates", file);
    for (size_t k = 0; k < s.contact_candidates.size(); ++k)
      contact.values<std::int32_t>(("tool_" + std::to_string(k)).c_str(), s.contact_candidates[k]);
    contact.close();
  }
  h5::set_int64_attribute(g.id(), "levels", static_cast<std::int64_t>(s.levels.size()),
                          {file, "/simulation"});
  for (size_t l = 0; l < s.levels.size(); ++l)
    write_level(g.id(), static_cast<int>(l), s.levels[l], file);
  g.close();
}

SimulationCheckpoint read_simulation(hid_t file_id, const std::string& file) {
  GroupReader g(file_id, "simulation", file);
  SimulationCheckpoint s;
  const std::vector<double> times = g.values<double>("times", 5);
  s.time = times[0];
  s.clock = times[1];
  s.external_at = times[2];
  s.dt = times[3];
  s.previous_dt = times[4];
  const std::vector<std::int64_t> counters = g.values<std::int64_t>("counters", 3);
  s.frames = counters[0];
  s.steps = counters[1];
  s.steps_per_frame = static_cast<std::int32_t>(counters[2]);
  s.block_evaluations = g.values<std::int64_t>("block_evaluations");
  s.tet_updates = g.values<std::int64_t>("tet_updates");
  s.time_level_evaluations = g.values<std::int64_t>("time_level_evaluations");
  {
    GroupReader contact(file_id, "simulation/contact_candidates", file);
    for (int k = 0; contact.has("tool_" + std::to_string(k)); ++k)
      s.contact_candidates.push_back(
          contact.values<std::int32_t>(("tool_" + std::to_string(k)).c_str()));
  }
  h5::Handle simulation = h5::checked(H5Gopen2(file_id, "simulation", H5P_DEFAULT), H5Gclose,
                                      {file, "/simulation"}, "open group");
  const std::int64_t levels =
      h5::read_int64_attribute(simulation.get(), "levels", {file, "/simulation"});
  if (levels < 1 || levels > 64)
    throw RunError(file + ": /simulation has " + std::to_string(levels) + " levels");
  for (int l = 0; l < levels; ++l) s.levels.push_back(read_level(simulation.get(), l, file));
  return s;
}

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const Checkpoint& c,
                      const std::filesystem::path& log) {
  replace_atomically(
      file,
      [&](const std::filesystem::path& tmp) {
        const std::string name = tmp.string();
        h5::silence_automatic_error_printing();
        h5::Handle f = h5::checked(
            H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
            {name, ""}, "create file");
        const h5::Where root{name, "/"};
        h5::set_string_attribute(f.get(), "format", kFormat, root);
        h5::set_int64_attribute(f.get(), "format_version", Checkpoint::kFormatVersion, root);
        h5::set_string_attribute(f.get(), "mrsim_version", c.mrsim_version, root);
        h5::set_string_attribute(f.get(), "git_revision", c.git_revision, root);
        h5::set_string_attribute(f.get(), "scenario", c.scenario_yaml, root);
        h5::set_string_attribute(f.get(), "scenario_source", c.scenario_source, root);
        write_run(f.get(), c.run, name);
        write_simulation(f.get(), c.simulation, name);
        h5::embed_file(f.get(), kLogDataset, log, {name, std::string("/") + kLogDataset});
        h5::check(f.close(), {name, ""}, "close file");
      },
      Durability::Synced);
}

namespace {

// The checkpoint file opened for reading once it is known to be one of this format.
h5::Handle open_checkpoint(const std::string& name) {
  h5::silence_automatic_error_printing();
  h5::Handle f = h5::checked(H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                             {name, ""}, "open file");
  const h5::Where root{name, "/"};
  if (!H5Aexists(f.get(), "format") ||
      h5::read_string_attribute(f.get(), "format", root) != kFormat)
    throw InputError(name + ": not an mrsim checkpoint");
  const std::int64_t version = h5::read_int64_attribute(f.get(), "format_version", root);
  if (version != Checkpoint::kFormatVersion)
    throw InputError(name + ": checkpoint format version " + std::to_string(version) +
                     "; this mrsim reads version " + std::to_string(Checkpoint::kFormatVersion));
  if (!h5::has_link(f.get(), kLogDataset, root))
    throw RunError(name + ": no /" + std::string(kLogDataset));
  return f;
}

}  // namespace

Checkpoint read_checkpoint(const std::filesystem::path& file) {
  const std::string name = file.string();
  if (!std::filesystem::is_regular_file(file))
    throw InputError(name +
                     ": no checkpoint here (a run writes one every "
                     "output.checkpoint_every frames and when it is interrupted)");
  try {
    h5::Handle f = open_checkpoint(name);
    const h5::Where root{name, "/"};
    Checkpoint c;
    c.mrsim_version = h5::read_string_attribute(f.get(), "mrsim_version", root);
    c.git_revision = h5::read_string_attribute(f.get(), "git_revision", root);
    c.scenario_yaml = h5::read_string_attribute(f.get(), "scenario", root);
    c.scenario_source = h5::read_string_attribute(f.get(), "scenario_source", root);
    c.run = read_run(f.get(), name);
    c.simulation = read_simulation(f.get(), name);
    return c;
  } catch (const RunError& e) {
    throw InputError(std::string("damaged checkpoint: ") + e.what());
  }
}

void restore_checkpoint_log(const std::filesystem::path& file, const std::filesystem::path& log) {
  const std::string name = file.string();
  h5::Handle f;
  try {
    f = open_checkpoint(name);
  } catch (const RunError& e) {
    throw InputError(std::string("damaged checkpoint: ") + e.what());
  }
  h5::extract_file(f.get(), kLogDataset, log, {name, std::string("/") + kLogDataset});
}

}  // namespace mrsim
