// Hdf5Log reopened to resume a run (issue 18, restart): the tables are cut back to the rows of
// the checkpoint's frame, and what is appended after that makes the log a run left alone would
// have written; a log of another scenario, or with fewer rows, is refused.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "h5_reader.hpp"
#include "io/hdf5_log.hpp"
#include "sample_log.hpp"
#include "temp_dir.hpp"

namespace mrsim {
namespace {

using test::append_sample_frame;
using test::H5Id;
using test::LogFixture;
using test::read_array;

// Frames 0..2 with one event per frame after frame 0, and a stray event of a frame never
// written (what a run killed mid-frame leaves): the run left alone.
void write_whole(const std::filesystem::path& path, const LogFixture& fixture) {
  Hdf5Log log(path, fixture.header());
  append_sample_frame(log, 0);
  log.append_event(1, "split", 1, 5);
  append_sample_frame(log, 1);
  log.append_event(2, "merge", 1, 6);
  append_sample_frame(log, 2);
}

TEST(Hdf5LogResume, CutsBackToTheCheckpointAndAppendsAsTheWholeRun) {
  test::TempDir dir;
  LogFixture fixture;
  write_whole(dir.path() / "whole.h5", fixture);
  const auto path = dir.path() / "resumed.h5";
  {
    Hdf5Log log(path, fixture.header());
    append_sample_frame(log, 0);
    log.append_event(1, "split", 1, 5);
    append_sample_frame(log, 1);  // the checkpoint: 2 frames, 1 event
    log.append_event(2, "merge", 1, 6);
    append_sample_frame(log, 2);
    log.append_event(3, "split", 0, 9);  // killed during frame 3
  }
  {
    Hdf5Log log(path, fixture.header(), Hdf5LogRows{2, 1, {}});
    const Hdf5LogRows rows = log.rows();
    EXPECT_EQ(rows.frames, 2);
    EXPECT_EQ(rows.events, 1);
    log.append_event(2, "merge", 1, 6);
    append_sample_frame(log, 2);
  }
  H5Id whole(test::open_read_only(dir.path() / "whole.h5"), H5Fclose);
  H5Id resumed(test::open_read_only(path), H5Fclose);
  for (const char* name : {"/frames/time", "/frames/kinetic_energy", "/frames/support_reaction"}) {
    const auto a = read_array<double>(whole, name), b = read_array<double>(resumed, name);
    EXPECT_EQ(a.dims, b.dims) << name;
    EXPECT_EQ(a.values, b.values) << name;
  }
  for (const char* name : {"/frames/active", "/frames/time_level_evaluations", "/events/point"}) {
    const auto a = read_array<std::int64_t>(whole, name),
               b = read_array<std::int64_t>(resumed, name);
    EXPECT_EQ(a.dims, b.dims) << name;
    EXPECT_EQ(a.values, b.values) << name;
  }
  const auto a = read_array<std::int8_t>(whole, "/levels/level_1/status");
  const auto b = read_array<std::int8_t>(resumed, "/levels/level_1/status");
  EXPECT_EQ(a.dims, b.dims);
  EXPECT_EQ(a.values, b.values);
  EXPECT_EQ(test::read_strings(resumed, "/events/kind"),
            (std::vector<std::string>{"split", "merge"}));
  // The header stays the run's: its start time is not the resumption's.
  EXPECT_EQ(test::read_string_attribute(resumed, "start_time"), "2026-01-02T03:04:05Z");
}

TEST(Hdf5LogResume, RefusesAnotherScenarioAndMissingRows) {
  test::TempDir dir;
  LogFixture fixture;
  const auto path = dir.path() / "log.h5";
  write_whole(path, fixture);
  Hdf5LogHeader other = fixture.header();
  other.scenario_yaml = "name: liver\n";
  EXPECT_THROW(Hdf5Log(path, other, Hdf5LogRows{2, 1, {}}), RunError);
  EXPECT_THROW(Hdf5Log(path, fixture.header(), Hdf5LogRows{4, 1, {}}), RunError);
  EXPECT_THROW(Hdf5Log(path, fixture.header(), Hdf5LogRows{2, 9, {}}), RunError);
  EXPECT_THROW(Hdf5Log(dir.path() / "none.h5", fixture.header(), Hdf5LogRows{1, 0, {}}), RunError);
  // Refused before anything was cut: the file still holds the whole run.
  H5Id file(test::open_read_only(path), H5Fclose);
  EXPECT_EQ(read_array<double>(file, "/frames/time").dims, (std::vector<hsize_t>{3}));
}

}  // namespace
}  // namespace mrsim
