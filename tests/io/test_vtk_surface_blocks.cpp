// VtkSeriesWriter's `surface` and `tool` blocks (the object's skin and the rigid tools), read
// back with VTK's own readers.
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/vtk_series_writer.hpp"
#include "vtk_read_checks.hpp"
#include "sample_frames.hpp"
#include "sample_tools.hpp"
#include "temp_dir.hpp"

namespace mrsim {
namespace {

using test::expect_scalars;
using test::expect_vectors;
using test::kSampleTimes;
using test::read_vtm;
using test::SampleSurface;
using test::SampleTool;

std::filesystem::path vtm_path(const std::filesystem::path& dir, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06d.vtm", frame);
  return dir / "frames" / name;
}

std::vector<std::string> block_names(vtkMultiBlockDataSet* blocks) {
  std::vector<std::string> names;
  for (unsigned b = 0; b < blocks->GetNumberOfBlocks(); ++b) {
    names.emplace_back(blocks->HasMetaData(b)
                           ? blocks->GetMetaData(b)->Get(vtkCompositeDataSet::NAME())
                           : "(unnamed)");
  }
  return names;
}

std::vector<std::string> piece_files(const std::filesystem::path& vtm) {
  std::ifstream in(vtm, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  const std::regex pattern(" file=\"([^\"]*)\"");
  std::vector<std::string> files;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), pattern);
       it != std::sregex_iterator(); ++it) {
    files.push_back((*it)[1].str());
  }
  return files;
}


void expect_points(vtkPolyData* block, const std::vector<Vec3>& expected) {
  ASSERT_EQ(block->GetNumberOfPoints(), static_cast<vtkIdType>(expected.size()));
  EXPECT_EQ(block->GetPoints()->GetDataType(), VTK_DOUBLE);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    double p[3];
    block->GetPoint(static_cast<vtkIdType>(i), p);
    for (int c = 0; c < 3; ++c) ASSERT_EQ(p[c], expected[i][c]) << "point " << i;
  }
}

// Triangles only (no vertices, lines or strips), with the given corners.
void expect_triangles(vtkPolyData* block, const std::vector<test::Triangle>& expected) {
  ASSERT_EQ(block->GetNumberOfCells(), static_cast<vtkIdType>(expected.size()));
  ASSERT_EQ(block->GetNumberOfPolys(), static_cast<vtkIdType>(expected.size()));
  for (vtkIdType t = 0; t < block->GetNumberOfCells(); ++t) {
    ASSERT_EQ(block->GetCellType(t), VTK_TRIANGLE) << "triangle " << t;
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    block->GetCellPoints(t, count, ids);
    ASSERT_EQ(count, 3);
    for (int c = 0; c < 3; ++c) ASSERT_EQ(ids[c], expected[t][c]) << "triangle " << t;
  }
}

void expect_time_value(vtkPolyData* block, double time) {
  vtkDataArray* time_value = block->GetFieldData()->GetArray("TimeValue");
  ASSERT_NE(time_value, nullptr);
  ASSERT_EQ(time_value->GetNumberOfTuples(), 1);
  EXPECT_EQ(time_value->GetComponent(0, 0), time);
}

void expect_surface_block(vtkPolyData* block, const SampleSurface& surface, double time) {
  ASSERT_NE(block, nullptr) << "surface is not a vtkPolyData";
  std::vector<Vec3> deformed;
  for (std::size_t i = 0; i < surface.rest.size(); ++i) {
    deformed.push_back(surface.rest[i] + surface.displacement[i]);
  }
  expect_points(block, deformed);
  expect_triangles(block, surface.triangles);
  vtkPointData* data = block->GetPointData();
  EXPECT_EQ(data->GetNumberOfArrays(), 4);
  expect_vectors(data, "displacement", surface.displacement);
  expect_vectors(data, "velocity", surface.velocity);
  expect_vectors(data, "contact_force", surface.contact_force);
  expect_scalars(data, "level", VTK_SIGNED_CHAR, surface.level);
  expect_time_value(block, time);
}

// All tools in one polydata: points concatenated in tool order, corners shifted accordingly.
void expect_tool_block(vtkPolyData* block, const std::vector<SampleTool>& tools, double time) {
  ASSERT_NE(block, nullptr) << "tool is not a vtkPolyData";
  std::vector<Vec3> points, forces;
  std::vector<test::Triangle> triangles;
  std::vector<std::int32_t> owner;
  for (std::size_t k = 0; k < tools.size(); ++k) {
    const int first = static_cast<int>(points.size());
    for (const test::Triangle& t : tools[k].triangles) {
      triangles.push_back({first + t[0], first + t[1], first + t[2]});
      owner.push_back(static_cast<std::int32_t>(k));
    }
    points.insert(points.end(), tools[k].points.begin(), tools[k].points.end());
    forces.push_back(tools[k].force);
  }
  expect_points(block, points);
  expect_triangles(block, triangles);
  EXPECT_EQ(block->GetCellData()->GetNumberOfArrays(), 1);
  expect_scalars(block->GetCellData(), "tool", VTK_INT, owner);
  EXPECT_EQ(block->GetPointData()->GetNumberOfArrays(), 0);
  expect_vectors(block->GetFieldData(), "force", forces);
  expect_time_value(block, time);
}

// Two frames with levels, skin and both tools; the sample data keeps the views alive.
void write_frames_with_tools(const std::filesystem::path& dir, int frames) {
  VtkSeriesWriter writer(dir);
  for (int f = 0; f < frames; ++f) {
    const auto levels = test::sample_frame(f);
    const SampleSurface surface(f);
    const SurfaceFrameView surface_view = surface.view();
    const auto tools = test::sample_tools(f);
    writer.write_frame(f, kSampleTimes[f], test::views_of(levels), &surface_view,
                       test::views_of(tools));
  }
}

TEST(VtkSurfaceBlocks, SurfaceAndToolBlocksFollowTheLevelBlocks) {
  test::TempDir dir;
  write_frames_with_tools(dir.path(), 2);
  for (int f = 0; f < 2; ++f) {
    auto blocks = read_vtm(vtm_path(dir.path(), f));
    ASSERT_NE(blocks, nullptr);
    ASSERT_EQ(block_names(blocks),
              (std::vector<std::string>{"level_0", "level_1", "surface", "tool"}));
    EXPECT_NE(vtkUnstructuredGrid::SafeDownCast(blocks->GetBlock(0)), nullptr);
    expect_surface_block(vtkPolyData::SafeDownCast(blocks->GetBlock(2)), SampleSurface(f),
                         kSampleTimes[f]);
    expect_tool_block(vtkPolyData::SafeDownCast(blocks->GetBlock(3)), test::sample_tools(f),
                      kSampleTimes[f]);
  }
}

TEST(VtkSurfaceBlocks, PiecesAreCompressedVtpFilesReadableAlone) {
  test::TempDir dir;
  write_frames_with_tools(dir.path(), 1);
  const auto vtm = vtm_path(dir.path(), 0);
  const auto pieces = piece_files(vtm);
  ASSERT_EQ(pieces.size(), 4u);
  EXPECT_EQ(std::filesystem::path(pieces[0]).extension(), ".vtu");
  for (std::size_t b = 2; b < 4; ++b) {
    const auto piece = vtm.parent_path() / pieces[b];
    ASSERT_EQ(piece.extension(), ".vtp") << piece;
    std::ifstream in(piece, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_NE(text.str().find("compressor=\"vtkLZ4DataCompressor\""), std::string::npos);  // default
    EXPECT_NE(text.str().find("format=\"appended\""), std::string::npos);
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    reader->SetFileName(piece.c_str());
    reader->Update();
    if (b == 2) {
      EXPECT_NE(text.str().find("type=\"Int8\" Name=\"level\""), std::string::npos);
      expect_surface_block(reader->GetOutput(), SampleSurface(0), kSampleTimes[0]);
    } else {
      expect_tool_block(reader->GetOutput(), test::sample_tools(0), kSampleTimes[0]);
    }
  }
}

TEST(VtkSurfaceBlocks, EachBlockIsWrittenOnlyWhenGiven) {
  test::TempDir dir;
  VtkSeriesWriter writer(dir.path());
  const auto levels = test::sample_frame(0);
  const SampleSurface surface(0);
  const SurfaceFrameView surface_view = surface.view();
  const auto tools = test::sample_tools(0);
  writer.write_frame(0, 0.0, test::views_of(levels), &surface_view);
  writer.write_frame(1, 0.04, test::views_of(levels), nullptr, test::views_of(tools));
  writer.write_frame(2, 0.08, test::views_of(levels), nullptr, {});
  EXPECT_EQ(block_names(read_vtm(vtm_path(dir.path(), 0))),
            (std::vector<std::string>{"level_0", "level_1", "surface"}));
  EXPECT_EQ(block_names(read_vtm(vtm_path(dir.path(), 1))),
            (std::vector<std::string>{"level_0", "level_1", "tool"}));
  EXPECT_EQ(block_names(read_vtm(vtm_path(dir.path(), 2))),
            (std::vector<std::string>{"level_0", "level_1"}));
  auto alone = read_vtm(vtm_path(dir.path(), 1));
  expect_tool_block(vtkPolyData::SafeDownCast(alone->GetBlock(2)), tools, 0.04);
}

// Writes frame 0 with the given skin and tools, expecting invalid_argument whose message
// contains `expected`, and no file.
void expect_rejected(const SurfaceFrameView* surface, const std::vector<ToolFrameView>& tools,
                     const std::string& expected) {
  test::TempDir dir;
  VtkSeriesWriter writer(dir.path());
  const auto levels = test::sample_frame(0);
  try {
    writer.write_frame(0, 0.0, test::views_of(levels), surface, tools);
    ADD_FAILURE() << "expected invalid_argument containing " << expected;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
  EXPECT_EQ(writer.frames_written(), 0);
  EXPECT_FALSE(std::filesystem::exists(vtm_path(dir.path(), 0)));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "frames.pvd"));
}

TEST(VtkSurfaceBlocks, RejectsSurfaceArraysOfTheWrongSize) {
  const SampleSurface surface(0);
  SurfaceFrameView view = surface.view();
  view.velocity = view.velocity.first(7);
  expect_rejected(&view, {}, "surface: velocity has 7 values, expected 8");
  view = surface.view();
  view.displacement = {};
  expect_rejected(&view, {}, "surface: displacement");
  view = surface.view();
  view.contact_force = view.contact_force.first(1);
  expect_rejected(&view, {}, "surface: contact_force");
  view = surface.view();
  view.level = view.level.first(5);
  expect_rejected(&view, {}, "surface: level");
}

TEST(VtkSurfaceBlocks, RejectsTriangleCornersOutOfRange) {
  SampleSurface surface(0);
  surface.triangles[5][1] = 8;  // one past the last vertex
  SurfaceFrameView view = surface.view();
  expect_rejected(&view, {}, "surface: triangle 5 refers to point 8 of 8");
  surface.triangles[5][1] = -1;
  view = surface.view();
  expect_rejected(&view, {}, "surface: triangle 5 refers to point -1");

  auto tools = test::sample_tools(0);
  tools[1].triangles[2][0] = 5;  // tool 1 has 5 points: the block would offset it into nothing
  expect_rejected(nullptr, test::views_of(tools), "tool 1: triangle 2 refers to point 5 of 5");
}

}  // namespace
}  // namespace mrsim
