// Hdf5Log's tool records: /tool, /tool_k (one row per simulation step) and /frames/tool_force,
// checked with the plain HDF5 C API.
#include <csignal>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "h5_reader.hpp"
#include "io/hdf5_log.hpp"
#include "sample_log.hpp"
#include "sample_tools.hpp"
#include "temp_dir.hpp"

namespace mrsim {
namespace {

using test::append_sample_frame;
using test::H5Id;
using test::LogFixture;
using test::read_array;
using test::SampleSteps;

const std::vector<ToolLogInfo> kTwoTools = {{"probe", "capsule"}, {"punch", "flat_cylinder"}};

LogFixture fixture_with(const std::vector<ToolLogInfo>& tools) {
  LogFixture fixture;
  fixture.tools = tools;
  return fixture;
}

bool exists(hid_t file, const char* path) { return H5Lexists(file, path, H5P_DEFAULT) > 0; }

// The samples tool `tool` would have after rows [0, rows) were appended, in one piece.
void expect_samples(hid_t file, const std::string& group, int tool, int rows) {
  const SampleSteps expected(tool, 0, rows);
  const auto n = static_cast<hsize_t>(rows);
  const auto time = read_array<double>(file, (group + "/time").c_str());
  const auto position = read_array<double>(file, (group + "/position").c_str());
  const auto orientation = read_array<double>(file, (group + "/orientation").c_str());
  const auto force = read_array<double>(file, (group + "/force").c_str());
  const auto contacts = read_array<std::int32_t>(file, (group + "/contacts").c_str());
  ASSERT_EQ(time.dims, (std::vector<hsize_t>{n})) << group;
  ASSERT_EQ(position.dims, (std::vector<hsize_t>{n, 3})) << group;
  ASSERT_EQ(orientation.dims, (std::vector<hsize_t>{n, 4})) << group;
  ASSERT_EQ(force.dims, (std::vector<hsize_t>{n, 3})) << group;
  ASSERT_EQ(contacts.dims, (std::vector<hsize_t>{n})) << group;
  EXPECT_EQ(time.values, expected.time) << group;
  EXPECT_EQ(contacts.values, expected.contacts) << group;
  for (std::size_t s = 0; s < expected.time.size(); ++s) {
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(position.values[3 * s + c], expected.position[s][c]) << group << " row " << s;
      ASSERT_EQ(force.values[3 * s + c], expected.force[s][c]) << group << " row " << s;
    }
    for (std::size_t c = 0; c < 4; ++c) {
      ASSERT_EQ(orientation.values[4 * s + c], expected.orientation[s][c]) << group << " row " << s;
    }
  }
}

void expect_tool_force(hid_t file, int frames, int tools) {
  const auto force = read_array<double>(file, "/frames/tool_force");
  ASSERT_EQ(force.dims, (std::vector<hsize_t>{static_cast<hsize_t>(frames),
                                              static_cast<hsize_t>(tools), 3}));
  for (int f = 0; f < frames; ++f) {
    for (int k = 0; k < tools; ++k) {
      const Vec3 expected = test::sample_tool_force(f, k);
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(force.values[(f * tools + k) * 3 + c], expected[c]) << f << " " << k;
      }
    }
  }
}

void append_steps(Hdf5Log& log, int tool, int first, int steps) {
  const SampleSteps samples(tool, first, steps);
  log.append_tool_samples(tool, samples.view());
}

TEST(Hdf5ToolLog, OneGroupPerToolNamedToolThenToolK) {
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  { Hdf5Log log(path, fixture_with({{"probe", "capsule"}, {"punch", "flat_cylinder"},
                                    {"ball", "sphere"}}).header()); }
  H5Id file(test::open_read_only(path), H5Fclose);
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"probe", "capsule"}, {"punch", "flat_cylinder"}, {"ball", "sphere"}};
  const char* const groups[] = {"/tool", "/tool_1", "/tool_2"};
  for (std::size_t k = 0; k < 3; ++k) {
    H5Id group(H5Gopen2(file, groups[k], H5P_DEFAULT), H5Gclose);
    EXPECT_EQ(test::read_string_attribute(group, "name"), expected[k].first) << groups[k];
    EXPECT_EQ(test::read_string_attribute(group, "shape"), expected[k].second) << groups[k];
    for (const char* name : {"time", "position", "orientation", "force", "contacts"}) {
      EXPECT_EQ(H5Lexists(group, name, H5P_DEFAULT), 1) << groups[k] << "/" << name;
    }
  }
  EXPECT_FALSE(exists(file, "/tool_0"));
  EXPECT_FALSE(exists(file, "/tool_3"));
  EXPECT_EQ(test::read_int_attribute(file, "format_version"), 1);  // additive: no bump
}

TEST(Hdf5ToolLog, SamplesOfSeveralFramesConcatenateInOrder) {
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  {
    Hdf5Log log(path, fixture_with(kTwoTools).header());
    append_steps(log, 0, 0, 1);
    append_steps(log, 1, 0, 0);  // no step for this tool: nothing appended
    append_sample_frame(log, 0, 2);
    append_steps(log, 1, 0, 2);  // tool order within a frame does not matter
    append_steps(log, 0, 1, 3);
    append_steps(log, 0, 4, 2);  // several batches in one frame
    append_sample_frame(log, 1, 2);
    append_steps(log, 0, 6, 4);
    append_steps(log, 1, 2, 1);
    append_sample_frame(log, 2, 2);
  }
  H5Id file(test::open_read_only(path), H5Fclose);
  expect_samples(file, "/tool", 0, 10);
  expect_samples(file, "/tool_1", 1, 3);
  expect_tool_force(file, 3, 2);
}

TEST(Hdf5ToolLog, DatasetsHaveFixedTypesUnitsDescriptionsAndChunks) {
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  { Hdf5Log log(path, fixture_with(kTwoTools).header()); }
  H5Id file(test::open_read_only(path), H5Fclose);
  struct Expected {
    const char* path;
    hid_t type;
    std::vector<hsize_t> row;
    const char* units;  // nullptr: no units attribute
  };
  const std::vector<Expected> datasets = {
      {"/tool/time", H5T_IEEE_F64LE, {}, "s"},
      {"/tool/position", H5T_IEEE_F64LE, {3}, "m"},
      {"/tool/orientation", H5T_IEEE_F64LE, {4}, nullptr},
      {"/tool/force", H5T_IEEE_F64LE, {3}, "N"},
      {"/tool/contacts", H5T_STD_I32LE, {}, nullptr},
      {"/tool_1/force", H5T_IEEE_F64LE, {3}, "N"},
      {"/frames/tool_force", H5T_IEEE_F64LE, {2, 3}, "N"}};
  for (const Expected& e : datasets) {
    EXPECT_TRUE(test::stored_as(file, e.path, e.type)) << e.path;
    H5Id dataset(H5Dopen2(file, e.path, H5P_DEFAULT), H5Dclose);
    std::vector<hsize_t> max_dims;
    const auto dims = test::dims_of(dataset, &max_dims);
    std::vector<hsize_t> empty{0};
    empty.insert(empty.end(), e.row.begin(), e.row.end());
    EXPECT_EQ(dims, empty) << e.path;  // present, with no row yet
    EXPECT_EQ(max_dims[0], H5S_UNLIMITED) << e.path;
    H5Id properties(H5Dget_create_plist(dataset), H5Pclose);
    ASSERT_EQ(H5Pget_layout(properties), H5D_CHUNKED) << e.path;
    std::vector<hsize_t> chunk(dims.size());
    H5Pget_chunk(properties, static_cast<int>(chunk.size()), chunk.data());
    EXPECT_GT(chunk[0], 1u) << e.path;
    // About 4 KiB: each frame's flush rewrites the last chunk whole.
    EXPECT_LE(test::chunk_bytes(dataset, chunk), 4096u) << e.path;
    if (e.units != nullptr) {
      EXPECT_EQ(test::read_string_attribute(dataset, "units"), e.units) << e.path;
    } else {
      EXPECT_EQ(H5Aexists(dataset, "units"), 0) << e.path;
    }
    EXPECT_FALSE(test::read_string_attribute(dataset, "description").empty()) << e.path;
  }
  H5Id time(H5Dopen2(file, "/tool/time", H5P_DEFAULT), H5Dclose);
  H5Id properties(H5Dget_create_plist(time), H5Pclose);
  hsize_t chunk = 0;
  H5Pget_chunk(properties, 1, &chunk);
  EXPECT_EQ(chunk, 512u);  // one row per step: more rows per chunk than /frames (128)
}

TEST(Hdf5ToolLog, WithoutToolsNoToolObjectExistsAndNoToolForceIsAccepted) {
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  {
    LogFixture fixture;
    Hdf5Log log(path, fixture.header());
    append_sample_frame(log, 0);
    const auto levels = test::sample_frame(1);
    try {
      log.append_frame(test::sample_record(1, levels, 1));
      ADD_FAILURE() << "expected invalid_argument";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("tool_force has 1 values, expected 0"),
                std::string::npos)
          << e.what();
    }
    const SampleSteps samples(0, 0, 1);
    EXPECT_THROW(log.append_tool_samples(0, samples.view()), std::invalid_argument);
  }
  H5Id file(test::open_read_only(path), H5Fclose);
  EXPECT_FALSE(exists(file, "/tool"));
  EXPECT_FALSE(exists(file, "/tool_1"));
  EXPECT_FALSE(exists(file, "/frames/tool_force"));
  EXPECT_EQ(test::dims_of(H5Id(H5Dopen2(file, "/frames/frame", H5P_DEFAULT), H5Dclose)),
            (std::vector<hsize_t>{1}));
}

TEST(Hdf5ToolLog, RejectsSamplesOfMismatchedLengthsWithoutAppendingAny) {
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  {
    Hdf5Log log(path, fixture_with(kTwoTools).header());
    const SampleSteps samples(1, 0, 3);
    const auto expect_refused = [&](const ToolSamples& bad, const std::string& array) {
      try {
        log.append_tool_samples(1, bad);
        ADD_FAILURE() << "expected invalid_argument for " << array;
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("tool 1 samples: " + array), std::string::npos)
            << e.what();
      }
    };
    ToolSamples bad = samples.view();
    bad.position = bad.position.first(2);
    expect_refused(bad, "position has 2 values, expected 3");
    bad = samples.view();
    bad.orientation = {};
    expect_refused(bad, "orientation");
    bad = samples.view();
    bad.force = bad.force.first(1);
    expect_refused(bad, "force");
    bad = samples.view();
    bad.contacts = bad.contacts.first(2);
    expect_refused(bad, "contacts");
    bad = samples.view();
    bad.time = bad.time.first(2);  // time sets the length: every other array is "wrong"
    expect_refused(bad, "position has 3 values, expected 2");
    EXPECT_THROW(log.append_tool_samples(2, samples.view()), std::invalid_argument);
    EXPECT_THROW(log.append_tool_samples(-1, samples.view()), std::invalid_argument);
    append_sample_frame(log, 0, 2);
  }
  H5Id file(test::open_read_only(path), H5Fclose);
  for (const char* name : {"/tool_1/time", "/tool_1/position", "/tool_1/orientation",
                           "/tool_1/force", "/tool_1/contacts", "/tool/time"}) {
    H5Id dataset(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose);
    EXPECT_EQ(test::dims_of(dataset)[0], 0u) << name;
  }
}

TEST(Hdf5ToolLog, RejectsFrameRecordsWithoutOneForcePerTool) {
  test::TempDir dir;
  Hdf5Log log(dir.path() / "log.h5", fixture_with(kTwoTools).header());
  const auto levels = test::sample_frame(0);
  for (const std::size_t count : {0u, 1u, 3u}) {
    try {
      log.append_frame(test::sample_record(0, levels, count));
      ADD_FAILURE() << "expected invalid_argument for " << count << " forces";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("tool_force has " + std::to_string(count) +
                                           " values, expected 2"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_NO_THROW(log.append_frame(test::sample_record(0, levels, 2)));
}

TEST(Hdf5ToolLog, ClosesEveryHdf5Id) {
  test::TempDir dir;
  {
    Hdf5Log log(dir.path() / "log.h5", fixture_with(kTwoTools).header());
    append_steps(log, 0, 0, 2);
    append_sample_frame(log, 0, 2);
  }
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

// A run killed mid-way (no destructor, no close) keeps the samples of every flushed frame;
// samples appended after the last frame may or may not be there.
TEST(Hdf5ToolLogDeathTest, KilledRunKeepsTheSamplesOfEveryFlushedFrame) {
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  EXPECT_EXIT(
      {
        Hdf5Log log(path, fixture_with(kTwoTools).header());
        append_steps(log, 0, 0, 3);
        append_steps(log, 1, 0, 2);
        append_sample_frame(log, 0, 2);
        append_steps(log, 0, 3, 4);
        append_sample_frame(log, 1, 2);
        append_steps(log, 0, 7, 5);  // never flushed
        append_steps(log, 1, 2, 5);
        std::raise(SIGKILL);
      },
      ::testing::KilledBySignal(SIGKILL), "");
  H5Id file(test::open_read_only(path), H5Fclose);
  EXPECT_EQ(read_array<std::int32_t>(file, "/frames/frame").values,
            (std::vector<std::int32_t>{0, 1}));
  expect_tool_force(file, 2, 2);
  H5Id group(H5Gopen2(file, "/tool_1", H5P_DEFAULT), H5Gclose);
  EXPECT_EQ(test::read_string_attribute(group, "shape"), "flat_cylinder");
  // The flushed rows, exactly; any later row is a complete sample too (time is written last).
  const auto time = read_array<double>(file, "/tool/time");
  ASSERT_GE(time.values.size(), 7u);
  const SampleSteps expected(0, 0, static_cast<int>(time.values.size()));
  EXPECT_EQ(time.values, expected.time);
  EXPECT_GE(read_array<double>(file, "/tool/position").dims[0], time.dims[0]);
  const auto contacts = read_array<std::int32_t>(file, "/tool_1/contacts");
  ASSERT_GE(contacts.values.size(), 2u);
  EXPECT_EQ(contacts.values[1], SampleSteps(1, 1, 1).contacts[0]);
}

}  // namespace
}  // namespace mrsim
