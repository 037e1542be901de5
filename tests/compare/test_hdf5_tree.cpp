// log.h5 comparison on small files written with the HDF5 C API: every dataset and attribute
// listed and read, shapes, items on one side only, ignored items, integers exact, the
// scenario attribute compared as a scenario, unreadable files as input errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "compare/compare_report.hpp"
#include "compare/hdf5_tree.hpp"
#include "compare/log_diff.hpp"
#include "compare/tolerance.hpp"
#include "core/error.hpp"
#include "h5_writer.hpp"
#include "io/temp_dir.hpp"

namespace mrsim {
namespace {

namespace fs = std::filesystem;

struct LogContent {
  std::vector<double> time{0.0, 0.02, 0.04};
  std::vector<double> wall_time{0.0, 0.1, 0.1};
  std::vector<std::int64_t> active{16, 0, 16, 4, 12, 9};  // [3, 2]
  std::size_t active_rows = 3;
  std::string start_time = "2024-01-01T00:00:00Z";
  std::string lambda = "5.0e+4";
  std::string output_dir = "out/a";
  bool with_events = true;
};

void write_log(const fs::path& file, const LogContent& c) {
  test::H5Writer w(file);
  w.doubles("/frames/time", {c.time.size()}, c.time);
  w.doubles("/frames/wall_time", {c.wall_time.size()}, c.wall_time);
  w.int64s("/frames/active", {c.active_rows, 2}, c.active);
  w.int8s("/levels/level_0/status", {3, 4}, {0, 1, 2, 2, 0, 1, 2, 2, 2, 2, 2, 2});
  if (c.with_events) w.strings("/events/kind", {"split", "merge"});
  w.string_attribute("/frames/time", "units", "s");
  w.int_attribute("/", "format_version", 1);
  w.string_attribute("/", "start_time", c.start_time);
  w.string_attribute(
      "/", "scenario",
      "material:\n  lambda: " + c.lambda + "\noutput:\n  dir: " + c.output_dir + "\n");
}

struct LogPair {
  test::TempDir dir;
  fs::path a = dir.path() / "a.h5";
  fs::path b = dir.path() / "b.h5";
  CompareReport compare(const LogContent& ca, const LogContent& cb, Tolerance t = {}) {
    write_log(a, ca);
    write_log(b, cb);
    CompareReport report("a", "b");
    diff_logs(a, b, t, report);
    return report;
  }
};

std::string printed(const CompareReport& report) {
  std::ostringstream out;
  report.print(out, {});
  return out.str();
}

TEST(Hdf5Tree, ListsEveryDatasetAndAttribute) {
  test::TempDir dir;
  write_log(dir.path() / "log.h5", {});
  const Hdf5Tree tree(dir.path() / "log.h5");
  std::vector<std::string> names;
  for (const Hdf5Item& item : tree.items()) names.push_back(item.name);
  const std::vector<std::string> expected{
      "/@format_version",   "/@scenario",        "/@start_time",
      "/events/kind",       "/frames/active",    "/frames/time",
      "/frames/time@units", "/frames/wall_time", "/levels/level_0/status"};
  EXPECT_EQ(names, expected);
}

TEST(Hdf5Tree, ReadsValuesShapesAndKinds) {
  test::TempDir dir;
  write_log(dir.path() / "log.h5", {});
  const Hdf5Tree tree(dir.path() / "log.h5");
  const auto item = [&](const std::string& name) {
    return *std::find_if(tree.items().begin(), tree.items().end(),
                         [&](const Hdf5Item& i) { return i.name == name; });
  };
  const ValueArray time = tree.read(item("/frames/time"));
  EXPECT_EQ(time.kind, ValueKind::Real);
  EXPECT_EQ(time.shape, Shape{3});
  EXPECT_EQ(time.reals[1], 0.02);
  const ValueArray status = tree.read(item("/levels/level_0/status"));
  EXPECT_EQ(status.kind, ValueKind::Integer);
  EXPECT_EQ(status.shape, (Shape{3, 4}));
  EXPECT_EQ(status.integers[2], 2);
  const ValueArray kind = tree.read(item("/events/kind"));
  EXPECT_EQ(kind.texts, (std::vector<std::string>{"split", "merge"}));
  const ValueArray units = tree.read(item("/frames/time@units"));
  EXPECT_TRUE(units.shape.empty());
  EXPECT_EQ(units.texts, std::vector<std::string>{"s"});
  EXPECT_EQ(tree.read(item("/@format_version")).integers, std::vector<std::int64_t>{1});
}

TEST(LogDiff, SameContentIsIdenticalAndIgnoredItemsAreListed) {
  LogPair pair;
  LogContent b;
  b.wall_time = {0.0, 7.0, 9.0};
  b.start_time = "2030-01-01T00:00:00Z";
  b.output_dir = "out/elsewhere";
  const CompareReport report = pair.compare({}, b);
  EXPECT_TRUE(report.identical()) << printed(report);
  EXPECT_EQ(report.compared_count(Section::Log), 7u);  // 9 items, wall_time and start_time ignored
  const std::string text = printed(report);
  EXPECT_NE(text.find("ignored: log.h5 /@scenario output.dir, /@start_time, /frames/wall_time"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("identical within rtol=0, atol=0"), std::string::npos) << text;
}

TEST(LogDiff, ReportsTheDatasetIndexAndBothValues) {
  LogPair pair;
  LogContent b;
  b.time[2] = 0.04 + 1e-9;
  const CompareReport report = pair.compare({}, b);
  ASSERT_EQ(report.lines().size(), 1u);
  EXPECT_EQ(report.lines()[0].subject, "log.h5 /frames/time [3]");
  EXPECT_NE(report.lines()[0].detail.find("1 of 3 values differ"), std::string::npos);
  EXPECT_NE(report.lines()[0].detail.find("at [2] (A 0.04, B 0.040000001)"), std::string::npos)
      << report.lines()[0].detail;
  EXPECT_TRUE(pair.compare({}, b, {0, 1e-8}).identical());
}

TEST(LogDiff, IntegersDifferWhateverTheTolerance) {
  LogPair pair;
  LogContent b;
  b.active[3] = 5;
  const CompareReport report = pair.compare({}, b, {1e9, 1e9});
  ASSERT_EQ(report.lines().size(), 1u);
  EXPECT_EQ(report.lines()[0].subject, "log.h5 /frames/active [3, 2]");
  EXPECT_NE(report.lines()[0].detail.find("at [1, 1] (A 4, B 5)"), std::string::npos)
      << report.lines()[0].detail;
}

TEST(LogDiff, ShapeMismatchReportsBothShapes) {
  LogPair pair;
  LogContent b;
  b.active_rows = 4;
  b.active.insert(b.active.end(), {1, 1});
  const CompareReport report = pair.compare({}, b);
  ASSERT_EQ(report.lines().size(), 1u);
  EXPECT_EQ(report.lines()[0].detail, "shapes differ: A [3, 2], B [4, 2]");
}

TEST(LogDiff, DatasetOnOneSideOnly) {
  LogPair pair;
  LogContent a;
  a.with_events = false;
  const CompareReport report = pair.compare(a, {});
  ASSERT_EQ(report.lines().size(), 1u);
  EXPECT_EQ(report.lines()[0].subject, "log.h5 /events/kind");
  EXPECT_EQ(report.lines()[0].detail, "only in B");
  EXPECT_EQ(report.differing(Section::Log), 1u);
}

TEST(LogDiff, ScenarioAttributeComparedAsAScenario) {
  LogPair pair;
  LogContent b;
  b.lambda = "6.0e+4";
  const CompareReport report = pair.compare({}, b);
  ASSERT_EQ(report.lines().size(), 1u);
  EXPECT_EQ(report.lines()[0].subject, "log.h5 /@scenario material.lambda");
  EXPECT_EQ(report.lines()[0].detail, "A 50000, B 60000");
}

TEST(LogDiff, UnreadableFilesAreInputErrorsNamingThem) {
  test::TempDir dir;
  write_log(dir.path() / "good.h5", {});
  CompareReport report("a", "b");
  EXPECT_THROW(diff_logs(dir.path() / "good.h5", dir.path() / "missing.h5", {}, report),
               InputError);
  std::ofstream(dir.path() / "bad.h5") << "not an HDF5 file";
  try {
    diff_logs(dir.path() / "good.h5", dir.path() / "bad.h5", {}, report);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.h5"), std::string::npos) << e.what();
  }
  // Cut in the middle: HDF5 notices the end of file is short.
  const auto size = fs::file_size(dir.path() / "good.h5");
  fs::copy_file(dir.path() / "good.h5", dir.path() / "cut.h5");
  fs::resize_file(dir.path() / "cut.h5", size / 2);
  EXPECT_THROW(diff_logs(dir.path() / "good.h5", dir.path() / "cut.h5", {}, report), InputError);
}

}  // namespace
}  // namespace mrsim
