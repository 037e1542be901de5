// checkpoint.h5 (issue 18, restart; docs/output.md "Checkpoints and --resume"): every field
// comes back bit for bit, the write is atomic (a failed write leaves the previous checkpoint),
// and what is not a whole checkpoint of this format is an InputError naming the file.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/error.hpp"
#include "io/checkpoint_file.hpp"
#include "temp_dir.hpp"

namespace mrsim {
namespace {

LevelCheckpoint sample_level(int n, int salt, bool time_levels) {
  LevelCheckpoint c;
  for (int i = 0; i < n; ++i) {
    const double x = std::sqrt(2.0) * (i + salt) + 1e-300;
    c.u.emplace_back(x, -x / 3, std::nextafter(x, 0.0));
    c.v.emplace_back(1e-17 * i, std::numeric_limits<double>::denorm_min(), -0.0);
    c.f.emplace_back(i, salt, 1.0 / 7.0);
    c.f_kick.emplace_back(-i, 0.5, 1e300);
    c.subdivided.push_back(static_cast<std::uint8_t>(i % 2));
    c.support.push_back(static_cast<std::uint8_t>((i + 1) % 2));
    c.active_ref.push_back(i * 3 + salt);
    c.ghost_ref.push_back(1 << 30);
    c.split_frame.push_back(i - 1);
    c.calm_streak.push_back(3 * i);
    if (time_levels) {
      c.time_level.push_back(static_cast<std::int8_t>(i % 5 - 1));
      c.stable_level.push_back(static_cast<std::int8_t>(i % 3));
    }
  }
  return c;
}

Checkpoint sample_checkpoint(bool time_levels) {
  Checkpoint c;
  c.mrsim_version = "0.1.0";
  c.git_revision = "abc1234";
  c.scenario_yaml = "name: beam\noutput:\n  dir: \"out/ä\"\n";
  c.scenario_source = "/somewhere/beam.yaml";
  c.run.frame = 17;
  c.run.frames_total = 70;
  c.run.max_displacement = 0.0123456789;
  c.run.splits = 5000000000LL;
  c.run.merges = 3;
  c.run.budget_hold = 2;
  c.run.budget_shed = 1;
  c.run.substep_changes = 4;
  c.run.peak_tool_force = 1.25;
  c.run.wall_time = 12.5;
  c.run.wall_time_parts = {1, 2, 3, 4, 5, 6, 7};
  c.run.log_events = 99;
  c.run.log_tool_samples = {340, 17};
  SimulationCheckpoint& s = c.simulation;
  s.time = 0.34000000000000002;
  s.clock = 0.33999999999999997;
  s.external_at = 0.34;
  s.dt = 0.02 / 256;
  s.frames = 17;
  s.steps = 4352;
  s.steps_per_frame = 256;
  s.previous_dt = 0.02 / 512;
  s.block_evaluations = {10, 20, (1LL << 40)};
  s.tet_updates = {7, (1LL << 42)};
  if (time_levels) s.time_level_evaluations = {1, 2, 3, 4};
  s.contact_candidates = {{1, 5, 9}, {}};
  s.levels = {sample_level(4, 0, time_levels), sample_level(9, 1, time_levels)};
  s.levels[1].u_prev = s.levels[1].u;  // one level with Newton–Cotes' arrays, one without
  s.levels[1].v_prev = s.levels[1].v;
  s.levels[0].f_kick.clear();
  return c;
}

void expect_same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(std::signbit(a[i][k]), std::signbit(b[i][k]));
  EXPECT_EQ(a, b);
}

void expect_equal(const Checkpoint& a, const Checkpoint& b) {
  EXPECT_EQ(a.mrsim_version, b.mrsim_version);
  EXPECT_EQ(a.git_revision, b.git_revision);
  EXPECT_EQ(a.scenario_yaml, b.scenario_yaml);
  EXPECT_EQ(a.scenario_source, b.scenario_source);
  EXPECT_EQ(a.run.frame, b.run.frame);
  EXPECT_EQ(a.run.frames_total, b.run.frames_total);
  EXPECT_EQ(a.run.max_displacement, b.run.max_displacement);
  EXPECT_EQ(a.run.splits, b.run.splits);
  EXPECT_EQ(a.run.merges, b.run.merges);
  EXPECT_EQ(a.run.budget_hold, b.run.budget_hold);
  EXPECT_EQ(a.run.budget_shed, b.run.budget_shed);
  EXPECT_EQ(a.run.substep_changes, b.run.substep_changes);
  EXPECT_EQ(a.run.peak_tool_force, b.run.peak_tool_force);
  EXPECT_EQ(a.run.wall_time, b.run.wall_time);
  EXPECT_EQ(a.run.wall_time_parts, b.run.wall_time_parts);
  EXPECT_EQ(a.run.log_events, b.run.log_events);
  EXPECT_EQ(a.run.log_tool_samples, b.run.log_tool_samples);
  const SimulationCheckpoint &s = a.simulation, &t = b.simulation;
  EXPECT_EQ(s.time, t.time);
  EXPECT_EQ(s.clock, t.clock);
  EXPECT_EQ(s.external_at, t.external_at);
  EXPECT_EQ(s.dt, t.dt);
  EXPECT_EQ(s.frames, t.frames);
  EXPECT_EQ(s.steps, t.steps);
  EXPECT_EQ(s.steps_per_frame, t.steps_per_frame);
  EXPECT_EQ(s.previous_dt, t.previous_dt);
  EXPECT_EQ(s.block_evaluations, t.block_evaluations);
  EXPECT_EQ(s.tet_updates, t.tet_updates);
  EXPECT_EQ(s.time_level_evaluations, t.time_level_evaluations);
  EXPECT_EQ(s.contact_candidates, t.contact_candidates);
  ASSERT_EQ(s.levels.size(), t.levels.size());
  for (size_t l = 0; l < s.levels.size(); ++l) {
    const LevelCheckpoint &x = s.levels[l], &y = t.levels[l];
    expect_same_bits(x.u, y.u);
    expect_same_bits(x.v, y.v);
    expect_same_bits(x.f, y.f);
    expect_same_bits(x.f_kick, y.f_kick);
    expect_same_bits(x.u_prev, y.u_prev);
    expect_same_bits(x.v_prev, y.v_prev);
    EXPECT_EQ(x.subdivided, y.subdivided);
    EXPECT_EQ(x.support, y.support);
    EXPECT_EQ(x.active_ref, y.active_ref);
    EXPECT_EQ(x.ghost_ref, y.ghost_ref);
    EXPECT_EQ(x.split_frame, y.split_frame);
    EXPECT_EQ(x.calm_streak, y.calm_streak);
    EXPECT_EQ(x.time_level, y.time_level);
    EXPECT_EQ(x.stable_level, y.stable_level);
  }
}

// A stand-in for log.h5: `size` bytes that are not all alike.
std::filesystem::path sample_log(const std::filesystem::path& dir, std::size_t size) {
  const auto file = dir / "log.h5";
  std::string bytes(size, '\0');
  for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<char>((i * 2654435761u) >> 13);
  std::ofstream(file, std::ios::binary) << bytes;
  return file;
}

std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(CheckpointFile, EveryFieldComesBackBitForBit) {
  test::TempDir dir;
  const auto log = sample_log(dir.path(), 1000);
  for (bool time_levels : {false, true}) {
    const Checkpoint c = sample_checkpoint(time_levels);
    write_checkpoint(dir.path() / kCheckpointFile, c, log);
    expect_equal(c, read_checkpoint(dir.path() / kCheckpointFile));
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "checkpoint.h5.tmp"));
  }
}

TEST(CheckpointFile, AFailedWriteLeavesThePreviousCheckpoint) {
  test::TempDir dir;
  const auto file = dir.path() / kCheckpointFile;
  const auto log = sample_log(dir.path(), 1000);
  Checkpoint first = sample_checkpoint(false);
  write_checkpoint(file, first, log);
  // The temporary file cannot be made: a directory is in its way.
  std::filesystem::create_directory(dir.path() / "checkpoint.h5.tmp");
  Checkpoint second = sample_checkpoint(true);
  second.run.frame = 18;
  EXPECT_THROW(write_checkpoint(file, second, log), RunError);
  expect_equal(first, read_checkpoint(file));
}

TEST(CheckpointFile, WhatIsNotAWholeCheckpointIsAnInputErrorNamingTheFile) {
  test::TempDir dir;
  const auto file = dir.path() / kCheckpointFile;
  const auto message_of = [&](const std::filesystem::path& f) -> std::string {
    try {
      read_checkpoint(f);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(read)";
  };
  EXPECT_NE(message_of(file).find("no checkpoint here"), std::string::npos);
  { std::ofstream(file) << "name: beam\n"; }
  EXPECT_NE(message_of(file).find("damaged checkpoint: " + file.string()), std::string::npos);
  write_checkpoint(file, sample_checkpoint(true), sample_log(dir.path(), 1000));
  const auto size = std::filesystem::file_size(file);
  std::filesystem::resize_file(file, size - 100);
  EXPECT_NE(message_of(file).find("damaged checkpoint"), std::string::npos);
  // An HDF5 file that is not a checkpoint (a log.h5, say).
  hid_t h = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  H5Fclose(h);
  EXPECT_NE(message_of(file).find("not an mrsim checkpoint"), std::string::npos);
}

// A run killed while it flushed log.h5 may leave it torn; the resumed run takes the copy the
// checkpoint holds, byte for byte (larger than one 4 MiB copy block, and empty).
TEST(CheckpointFile, TheLogComesBackByteForByteOverATornOne) {
  test::TempDir dir;
  const auto file = dir.path() / kCheckpointFile;
  for (std::size_t size : {std::size_t{(9 << 20) + 123}, std::size_t{0}}) {
    const auto log = sample_log(dir.path(), size);
    const std::string written = contents(log);
    write_checkpoint(file, sample_checkpoint(false), log);
    std::filesystem::resize_file(log, size / 3);
    { std::ofstream(log, std::ios::app) << "torn"; }
    restore_checkpoint_log(file, log);
    EXPECT_EQ(contents(log), written) << size << " bytes";
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "log.h5.tmp"));
  }
  // Without a checkpoint's log there is nothing to go on from: a damaged checkpoint.
  hid_t h = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  H5Fclose(h);
  EXPECT_THROW(restore_checkpoint_log(file, dir.path() / "log.h5"), InputError);
}

}  // namespace
}  // namespace mrsim
