// Hdf5Log: layout, values, attributes, chunking, crash safety and error reporting of log.h5,
// checked with the plain HDF5 C API.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <fstream>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "h5_reader.hpp"
#include "io/hdf5_log.hpp"
#include "sample_frames.hpp"
#include "sample_log.hpp"
#include "temp_dir.hpp"

namespace mrsim {
namespace {

using test::append_sample_frame;
using test::Array;
using test::H5Id;
using test::kSampleTimes;
using test::kScenario;
using test::LogFixture;
using test::read_array;
using test::sample_record;

// Checks the first `frames` frames of the sample run in an open file.
void expect_frames(hid_t file, int frames) {
  const auto n = static_cast<hsize_t>(frames);
  const auto time = read_array<double>(file, "/frames/time");
  ASSERT_EQ(time.dims, (std::vector<hsize_t>{n}));
  const auto kinetic = read_array<double>(file, "/frames/kinetic_energy");
  const auto elastic = read_array<double>(file, "/frames/elastic_energy");
  const auto wall = read_array<double>(file, "/frames/wall_time");
  const auto frame = read_array<std::int32_t>(file, "/frames/frame");
  const auto active = read_array<std::int64_t>(file, "/frames/active");
  const auto ghosts = read_array<std::int64_t>(file, "/frames/ghosts");
  const auto evaluations = read_array<std::int64_t>(file, "/frames/force_evaluations");
  const auto tet_updates = read_array<std::int64_t>(file, "/frames/tet_updates");
  ASSERT_EQ(tet_updates.dims, (std::vector<hsize_t>{n, 2}));
  ASSERT_EQ(active.dims, (std::vector<hsize_t>{n, 2}));
  ASSERT_EQ(ghosts.dims, (std::vector<hsize_t>{n, 2}));
  ASSERT_EQ(evaluations.dims, (std::vector<hsize_t>{n, 2}));
  const auto time_levels = read_array<std::int64_t>(file, "/frames/time_levels");
  const auto time_level_evaluations = read_array<std::int64_t>(file, "/frames/time_level_evaluations");
  const auto steps = read_array<double>(file, "/frames/time_level_step");
  ASSERT_EQ(time_levels.dims, (std::vector<hsize_t>{n, 3}));
  ASSERT_EQ(time_level_evaluations.dims, (std::vector<hsize_t>{n, 3}));
  EXPECT_EQ(steps.values, (std::vector<double>{0.04, 0.02, 0.01}));
  for (int f = 0; f < frames; ++f) {
    const auto levels = test::sample_frame(f);
    const FrameRecord r = sample_record(f, levels);
    EXPECT_EQ(time.values[f], r.time);
    EXPECT_EQ(kinetic.values[f], r.kinetic_energy);
    EXPECT_EQ(elastic.values[f], r.elastic_energy);
    EXPECT_EQ(wall.values[f], r.wall_time);
    EXPECT_EQ(frame.values[f], f);
    for (int k = 0; k < 2; ++k) {
      EXPECT_EQ(active.values[2 * f + k], r.active[k]);
      EXPECT_EQ(ghosts.values[2 * f + k], r.ghosts[k]);
      EXPECT_EQ(evaluations.values[2 * f + k], r.force_evaluations[k]);
      EXPECT_EQ(tet_updates.values[2 * f + k], r.tet_updates[k]);
    }
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(time_levels.values[3 * f + k], r.time_levels[k]);
      EXPECT_EQ(time_level_evaluations.values[3 * f + k], r.time_level_evaluations[k]);
    }
    for (int k = 0; k < 2; ++k) {
      const std::string path = "/levels/level_" + std::to_string(k) + "/status";
      const auto status = read_array<std::int8_t>(file, path.c_str());
      const hsize_t points = levels[k].mesh.points.size();
      ASSERT_EQ(status.dims, (std::vector<hsize_t>{n, points}));
      for (hsize_t i = 0; i < points; ++i) {
        ASSERT_EQ(status.values[f * points + i], levels[k].status[i]) << path << " " << f << " " << i;
      }
    }
  }
}

void expect_levels(hid_t file, const std::vector<test::SampleLevel>& levels) {
  H5Id group(H5Gopen2(file, "/levels", H5P_DEFAULT), H5Gclose);
  EXPECT_EQ(test::read_int_attribute(group, "count"), 2);
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const std::string base = "/levels/level_" + std::to_string(k);
    const TetMesh& mesh = levels[k].mesh;
    const auto rest = read_array<double>(file, (base + "/rest_positions").c_str());
    ASSERT_EQ(rest.dims, (std::vector<hsize_t>{mesh.points.size(), 3}));
    for (std::size_t i = 0; i < mesh.points.size(); ++i) {
      for (int c = 0; c < 3; ++c) ASSERT_EQ(rest.values[3 * i + c], mesh.points[i][c]);
    }
    const auto tets = read_array<std::int32_t>(file, (base + "/tets").c_str());
    ASSERT_EQ(tets.dims, (std::vector<hsize_t>{mesh.tets.size(), 4}));
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      for (int c = 0; c < 4; ++c) ASSERT_EQ(tets.values[4 * t + c], mesh.tets[t][c]);
    }
  }
}

TEST(Hdf5Log, WritesHeaderLevelsFramesAndEvents) {
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  LogFixture fixture;
  {
    Hdf5Log log(path, fixture.header());
    append_sample_frame(log, 0);
    log.append_event(1, "split", 1, 5);
    log.append_event(1, "time_level", 0, 3000000000LL);
    append_sample_frame(log, 1);
    append_sample_frame(log, 2);
    log.append_event(2, "merge", 1, -1);  // after the last frame: written by close()
  }
  H5Id file(test::open_read_only(path), H5Fclose);
  EXPECT_EQ(test::read_string_attribute(file, "mrsim_version"), "0.1.0");
  EXPECT_EQ(test::read_string_attribute(file, "git_revision"), "abc1234");
  EXPECT_EQ(test::read_string_attribute(file, "scenario"), kScenario);
  EXPECT_EQ(test::read_string_attribute(file, "start_time"), "2026-01-02T03:04:05Z");
  EXPECT_EQ(test::read_int_attribute(file, "format_version"), 1);
  expect_levels(file, fixture.first);
  expect_frames(file, 3);

  const auto event_frame = read_array<std::int32_t>(file, "/events/frame");
  const auto event_level = read_array<std::int32_t>(file, "/events/level");
  const auto event_point = read_array<std::int64_t>(file, "/events/point");
  EXPECT_EQ(event_frame.values, (std::vector<std::int32_t>{1, 1, 2}));
  EXPECT_EQ(event_level.values, (std::vector<std::int32_t>{1, 0, 1}));
  EXPECT_EQ(event_point.values, (std::vector<std::int64_t>{5, 3000000000LL, -1}));
  EXPECT_EQ(test::read_strings(file, "/events/kind"),
            (std::vector<std::string>{"split", "time_level", "merge"}));
}

TEST(Hdf5Log, StoresLongScenarioTextWhole) {
  // Object headers hold at most 64 KiB; a long resolved scenario must still fit.
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  LogFixture fixture;
  Hdf5LogHeader header = fixture.header();
  header.scenario_yaml.clear();
  for (int i = 0; header.scenario_yaml.size() < 200'000; ++i) {
    header.scenario_yaml += "key_" + std::to_string(i) + ": value\n";
  }
  { Hdf5Log log(path, header); }
  H5Id file(test::open_read_only(path), H5Fclose);
  EXPECT_EQ(test::read_string_attribute(file, "scenario"), header.scenario_yaml);
}

TEST(Hdf5Log, StoresFixedLittleEndianTypesAndUnits) {
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  LogFixture fixture;
  {
    Hdf5Log log(path, fixture.header());
    append_sample_frame(log, 0);
  }
  H5Id file(test::open_read_only(path), H5Fclose);
  EXPECT_TRUE(test::stored_as(file, "/frames/time", H5T_IEEE_F64LE));
  EXPECT_TRUE(test::stored_as(file, "/frames/active", H5T_STD_I64LE));
  EXPECT_TRUE(test::stored_as(file, "/frames/frame", H5T_STD_I32LE));
  EXPECT_TRUE(test::stored_as(file, "/levels/level_0/status", H5T_STD_I8LE));
  EXPECT_TRUE(test::stored_as(file, "/levels/level_0/rest_positions", H5T_IEEE_F64LE));
  EXPECT_TRUE(test::stored_as(file, "/levels/level_0/tets", H5T_STD_I32LE));
  EXPECT_TRUE(test::stored_as(file, "/events/point", H5T_STD_I64LE));
  H5Id time(H5Dopen2(file, "/frames/time", H5P_DEFAULT), H5Dclose);
  EXPECT_EQ(test::read_string_attribute(time, "units"), "s");
  H5Id energy(H5Dopen2(file, "/frames/kinetic_energy", H5P_DEFAULT), H5Dclose);
  EXPECT_EQ(test::read_string_attribute(energy, "units"), "J");
  H5Id rest(H5Dopen2(file, "/levels/level_1/rest_positions", H5P_DEFAULT), H5Dclose);
  EXPECT_EQ(test::read_string_attribute(rest, "units"), "m");
}

TEST(Hdf5Log, PerFrameDatasetsAreChunkedAndUnlimited) {
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  LogFixture fixture;
  { Hdf5Log log(path, fixture.header()); }
  H5Id file(test::open_read_only(path), H5Fclose);
  for (const char* name : {"/frames/time", "/frames/kinetic_energy", "/frames/elastic_energy",
                           "/frames/wall_time", "/frames/active", "/frames/ghosts",
                           "/frames/force_evaluations", "/frames/frame", "/levels/level_0/status",
                           "/levels/level_1/status", "/events/frame", "/events/kind",
                           "/events/level", "/events/point"}) {
    H5Id dataset(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose);
    std::vector<hsize_t> max_dims;
    const auto dims = test::dims_of(dataset, &max_dims);
    EXPECT_EQ(dims[0], 0u) << name;  // no frame appended: empty but present
    EXPECT_EQ(max_dims[0], H5S_UNLIMITED) << name;
    H5Id properties(H5Dget_create_plist(dataset), H5Pclose);
    EXPECT_EQ(H5Pget_layout(properties), H5D_CHUNKED) << name;
    std::vector<hsize_t> chunk(dims.size());
    H5Pget_chunk(properties, static_cast<int>(chunk.size()), chunk.data());
    if (std::string(name).starts_with("/frames/")) {
      EXPECT_LE(chunk[0], 128u) << name;
    }
    // Each frame's flush rewrites the last chunk of every growing dataset whole: small chunks
    // keep what a frame writes small.
    if (!std::string(name).ends_with("/status")) {
      EXPECT_LE(test::chunk_bytes(dataset, chunk), 4096u) << name;
    }
    // Compressed chunks are never rewritten: one frame each (hdf5_level_group.cpp says why).
    if (std::string(name).ends_with("/status")) {
      EXPECT_EQ(chunk[0], 1u) << name;
    }
  }
}

// Each frame's flush writes whole pages (hdf5_log.cpp says why): the file space is paged, and
// the superblock stays at version 2, which HDF5 opens after a killed run (version 3 would keep
// an "open for writing" mark and refuse it).
TEST(Hdf5Log, FileSpaceIsPagedUnderAVersion2Superblock) {
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  LogFixture fixture;
  { Hdf5Log log(path, fixture.header()); }
  H5Id file(test::open_read_only(path), H5Fclose);
  H5Id creation(H5Fget_create_plist(file), H5Pclose);
  H5F_fspace_strategy_t strategy{};
  hbool_t persist = true;
  hsize_t threshold = 0, page = 0;
  ASSERT_GE(H5Pget_file_space_strategy(creation, &strategy, &persist, &threshold), 0);
  EXPECT_EQ(strategy, H5F_FSPACE_STRATEGY_PAGE);
  EXPECT_FALSE(persist);
  ASSERT_GE(H5Pget_file_space_page_size(creation, &page), 0);
  EXPECT_EQ(page, 16u * 1024);
  unsigned superblock = 0;
  ASSERT_GE(H5Pget_version(creation, &superblock, nullptr, nullptr, nullptr), 0);
  EXPECT_EQ(superblock, 2u);
}

// zlib's set-up is paid per chunk, so per frame: a level's status rows are deflated from 1024
// points on, where they save more than they cost, and stored as they are below.
TEST(Hdf5Log, StatusRowsAreDeflatedFromAThousandPointsOn) {
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  LogFixture fixture;
  TetMesh large;
  large.points.assign(1024, Vec3::Zero());
  large.tets = {{0, 1, 2, 3}};
  TetMesh small = large;
  small.points.resize(1023);
  Hdf5LogHeader header = fixture.header();
  header.levels = {&small, &large};
  { Hdf5Log log(path, header); }
  H5Id file(test::open_read_only(path), H5Fclose);
  for (const auto& [name, filters] : {std::pair{"/levels/level_0/status", 0},
                                      std::pair{"/levels/level_1/status", 1}}) {
    H5Id status(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose);
    H5Id properties(H5Dget_create_plist(status), H5Pclose);
    ASSERT_EQ(H5Pget_nfilters(properties), filters) << name;
    if (filters == 0) continue;
    unsigned flags = 0, level = 0;
    std::size_t values = 1;
    char filter_name[16];
    EXPECT_EQ(H5Pget_filter2(properties, 0, &flags, &values, &level, sizeof filter_name,
                             filter_name, nullptr),
              H5Z_FILTER_DEFLATE);
    EXPECT_EQ(level, 4u);
  }
}

TEST(Hdf5Log, ClosesEveryHdf5Id) {
  test::TempDir dir;
  LogFixture fixture;
  {
    Hdf5Log log(dir.path() / "log.h5", fixture.header());
    append_sample_frame(log, 0);
    log.append_event(0, "split", 0, 1);
    EXPECT_GT(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
  }
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

TEST(Hdf5Log, ExplicitCloseThenUseIsALogicError) {
  test::TempDir dir;
  LogFixture fixture;
  Hdf5Log log(dir.path() / "log.h5", fixture.header());
  append_sample_frame(log, 0);
  log.close();
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
  log.close();  // idempotent
  EXPECT_THROW(append_sample_frame(log, 1), std::logic_error);
  EXPECT_THROW(log.append_event(1, "split", 0, 0), std::logic_error);
  EXPECT_THROW(log.append_tool_samples(0, ToolSamples{}), std::logic_error);
}

TEST(Hdf5Log, UnwritableLocationThrowsRunErrorNamingTheFileWithoutLeaks) {
  test::TempDir dir;
  const auto blocker = dir.path() / "not_a_folder";
  std::ofstream(blocker) << "x";
  LogFixture fixture;
  try {
    Hdf5Log log(blocker / "log.h5", fixture.header());
    FAIL() << "expected RunError";
  } catch (const RunError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("not_a_folder/log.h5"), std::string::npos) << message;
    EXPECT_NE(message.find("create file"), std::string::npos) << message;
  }
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

TEST(Hdf5Log, RejectsRecordsOfTheWrongShape) {
  test::TempDir dir;
  LogFixture fixture;
  Hdf5Log log(dir.path() / "log.h5", fixture.header());
  const auto levels = test::sample_frame(0);
  FrameRecord r = sample_record(0, levels);
  r.status[1] = r.status[1].first(3);
  try {
    log.append_frame(r);
    FAIL() << "expected invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("level_1: status"), std::string::npos) << e.what();
  }
  r = sample_record(0, levels);
  r.active.pop_back();
  EXPECT_THROW(log.append_frame(r), std::invalid_argument);
  r = sample_record(0, levels);
  r.time_levels.pop_back();
  EXPECT_THROW(log.append_frame(r), std::invalid_argument);
}

// A run killed mid-way (no destructor, no close) leaves a file that opens and holds every
// frame appended so far.
TEST(Hdf5LogDeathTest, KilledRunLeavesReadableFileWithFlushedFrames) {
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  EXPECT_EXIT(
      {
        LogFixture fixture;
        Hdf5Log log(path, fixture.header());
        append_sample_frame(log, 0);
        log.append_event(1, "split", 1, 7);
        append_sample_frame(log, 1);
        std::raise(SIGKILL);
      },
      ::testing::KilledBySignal(SIGKILL), "");
  H5Id file(test::open_read_only(path), H5Fclose);
  EXPECT_EQ(test::read_string_attribute(file, "scenario"), kScenario);
  expect_levels(file, LogFixture().first);
  expect_frames(file, 2);
  EXPECT_EQ(read_array<std::int64_t>(file, "/events/point").values,
            (std::vector<std::int64_t>{7}));
}

// A live run's log can be read by another process (e.g. a plotting script) after each frame,
// provided the reader does not insist on file locking (HDF5_USE_FILE_LOCKING=FALSE).
TEST(Hdf5Log, ReadableByAnotherProcessWhileTheWriterIsAlive) {
  test::TempDir dir;
  const auto path = dir.path() / "log.h5";
  const pid_t writer = fork();
  ASSERT_GE(writer, 0);
  if (writer == 0) {
    try {
      LogFixture fixture;
      Hdf5Log log(path, fixture.header());
      for (int f = 0; f < 3; ++f) append_sample_frame(log, f);
      raise(SIGSTOP);  // the writer object is alive, the file open, while the parent reads
    } catch (...) {
      _exit(3);
    }
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(writer, &status, WUNTRACED), writer);
  ASSERT_TRUE(WIFSTOPPED(status)) << "writer ended early with status " << status;
  {
    H5Id file(test::open_read_only(path, /*file_locking=*/false), H5Fclose);
    expect_frames(file, 3);
  }
  kill(writer, SIGKILL);
  waitpid(writer, &status, 0);
}

}  // namespace
}  // namespace mrsim
