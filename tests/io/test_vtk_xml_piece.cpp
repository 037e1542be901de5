// VtkXmlPiece: a frame's block in the bytes VTK's own XML writers give it (appended raw binary,
// UInt64 headers, each compression), and what it leaves to them.
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkLongLongArray.h>
#include <vtkPointData.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedShortArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "io/frame_compression.hpp"
#include "io/vtk_level_grid.hpp"
#include "io/vtk_repeat_compressor.hpp"
#include "io/vtk_series_writer.hpp"
#include "io/vtk_surface_blocks.hpp"
#include "io/vtk_xml_piece.hpp"
#include "mesh/box_mesh.hpp"
#include "sample_frames.hpp"
#include "sample_tools.hpp"
#include "temp_dir.hpp"

namespace mrsim {
namespace {

// What VTK's writer for `block` writes with the frames' settings and a compressor of `kind`.
std::string vtk_bytes(vtkDataObject* block, FrameCompression kind) {
  FrameCompressor compressor(kind);
  vtkSmartPointer<vtkXMLWriter> writer;
  if (vtkUnstructuredGrid::SafeDownCast(block) != nullptr)
    writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
  else
    writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  writer->SetInputData(block);
  if (compressor.get() != nullptr)
    writer->SetCompressor(compressor.get());
  else
    writer->SetCompressorTypeToNone();
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetHeaderTypeToUInt64();
  writer->WriteToOutputStringOn();
  EXPECT_EQ(writer->Write(), 1);
  return writer->GetOutputString();
}

std::string our_bytes(vtkDataObject* block, FrameCompression kind) {
  FrameCompressor compressor(kind);
  VtkXmlPiece piece;
  std::string out;
  EXPECT_TRUE(piece.write(block, compressor.get(), out));
  return out;
}

// Ours first: VTK's writer leaves each array's range cached in its information, which this
// writer leaves to VTK's (LeavesToVtkWhatOnlyVtkWritesExactly).
void expect_vtk_bytes(vtkDataObject* block, FrameCompression kind) {
  const std::string ours = our_bytes(block, kind);
  EXPECT_EQ(ours, vtk_bytes(block, kind));
}

class XmlPieceCompression : public ::testing::TestWithParam<FrameCompression> {};

// A level's grid large enough for arrays of many 32 KiB blocks, one of exactly one block (4096
// doubles: no partial last block), and arrays of every kind the writer takes: component names,
// an active scalar, Float32, UInt16 and Int64 values, negative integers.
vtkSmartPointer<vtkUnstructuredGrid> large_grid() {
  static const TetMesh mesh = make_box_mesh(Vec3(0, 0, 0), Vec3(0.4, 0.2, 0.1), 48, 24, 12);
  static test::SampleLevel level(0, 2);
  level.mesh = mesh;
  const std::size_t n = mesh.points.size();
  level.displacement.assign(n, Vec3(1e-3, -2e-3, 3e-4));
  for (std::size_t i = 0; i < n; ++i) level.displacement[i] *= std::sin(0.1 * i);
  level.velocity.assign(n, Vec3(0.5, 0, -1));
  level.force.assign(n, Vec3::Zero());
  level.status.assign(n, 2);
  level.time_level.assign(n, -1);
  level.criterion.assign(n, 1.0 / 3.0);
  level.mass.assign(n, 0.25);
  auto grid = make_level_grid(level.view(), 0.12);
  auto names = vtkSmartPointer<vtkFloatArray>::New();
  names->SetName("principal");
  names->SetNumberOfComponents(2);
  names->SetComponentName(0, "first");
  names->SetComponentName(1, "second");
  names->SetNumberOfTuples(static_cast<vtkIdType>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const float value[2] = {1.5f, -0.25f * static_cast<float>(i % 5)};
    names->SetTypedTuple(static_cast<vtkIdType>(i), value);
  }
  grid->GetPointData()->AddArray(names);
  auto exact = vtkSmartPointer<vtkDoubleArray>::New();
  exact->SetName("one_block");
  exact->SetNumberOfTuples(4096);
  for (vtkIdType i = 0; i < 4096; ++i) exact->SetValue(i, std::cos(0.01 * i) * 1e5);
  grid->GetFieldData()->AddArray(exact);
  auto shorts = vtkSmartPointer<vtkUnsignedShortArray>::New();
  shorts->SetName("shorts");
  shorts->SetNumberOfTuples(grid->GetNumberOfCells());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) shorts->SetValue(c, c % 7000);
  grid->GetCellData()->AddArray(shorts);
  grid->GetCellData()->SetActiveScalars("shorts");
  auto longs = vtkSmartPointer<vtkLongLongArray>::New();
  longs->SetName("longs");
  longs->SetNumberOfTuples(grid->GetNumberOfCells());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) longs->SetValue(c, -c * 1000003);
  grid->GetCellData()->AddArray(longs);
  return grid;
}

TEST_P(XmlPieceCompression, LevelGridsAreTheBytesOfVtksWriter) {
  const auto levels = test::sample_frame(1);
  for (const auto& level : levels) {
    auto grid = make_level_grid(level.view(), test::kSampleTimes[1]);
    expect_vtk_bytes(grid, GetParam());
  }
  auto grid = large_grid();
  ASSERT_GT(grid->GetNumberOfPoints() * 24, 8 * 32768);  // many blocks per vector array
  expect_vtk_bytes(grid, GetParam());
}

TEST_P(XmlPieceCompression, SurfaceAndToolBlocksAreTheBytesOfVtksWriter) {
  const test::SampleSurface surface(1);
  const SurfaceFrameView view = surface.view();
  auto skin = make_surface_block(view, test::kSampleTimes[1]);
  expect_vtk_bytes(skin, GetParam());
  const auto tools = test::sample_tools(1);
  const auto views = test::views_of(tools);
  auto tool = make_tool_block(views, test::kSampleTimes[1]);
  expect_vtk_bytes(tool, GetParam());
}

INSTANTIATE_TEST_SUITE_P(VtkXmlPiece, XmlPieceCompression,
                         ::testing::Values(FrameCompression::Lz4, FrameCompression::Zlib,
                                           FrameCompression::None),
                         [](const auto& info) {
                           switch (info.param) {
                             case FrameCompression::Lz4: return std::string("LZ4");
                             case FrameCompression::Zlib: return std::string("ZLib");
                             default: return std::string("None");
                           }
                         });

// Every block of the frames mrsim writes (levels, skin, tools) goes through VtkXmlPiece: none is
// left to VTK's writer.
TEST(VtkXmlPiece, WritesEveryBlockOfTheSeries) {
  test::TempDir dir;
  VtkSeriesWriter writer(dir.path());
  for (int f = 0; f < 3; ++f) {
    const auto levels = test::sample_frame(f);
    const test::SampleSurface surface(f);
    const SurfaceFrameView skin = surface.view();
    const auto tools = test::sample_tools(f);
    writer.write_frame(f, test::kSampleTimes[f], test::views_of(levels), &skin,
                       test::views_of(tools));
  }
  EXPECT_EQ(writer.frames_written(), 3);
  EXPECT_EQ(writer.pieces_written_by_vtk(), 0u);
}

// A block left to VTK (a NaN in a level: VTK's ranges skip it) is still written, by VTK's
// writer, and reads back with its NaN.
TEST(VtkXmlPiece, ABlockLeftToVtkIsWrittenByVtk) {
  test::TempDir dir;
  VtkSeriesWriter writer(dir.path());
  auto levels = test::sample_frame(0);
  levels[1].criterion[2] = std::numeric_limits<double>::quiet_NaN();
  writer.write_frame(0, 0.0, test::views_of(levels));
  EXPECT_EQ(writer.pieces_written_by_vtk(), 1u);
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  const auto piece = dir.path() / "frames" / "frame_000000" / "frame_000000_1.vtu";
  reader->SetFileName(piece.c_str());
  reader->Update();
  vtkDataArray* criterion = reader->GetOutput()->GetPointData()->GetArray("criterion");
  ASSERT_NE(criterion, nullptr);
  EXPECT_TRUE(std::isnan(criterion->GetComponent(2, 0)));
  EXPECT_EQ(criterion->GetComponent(3, 0), levels[1].criterion[3]);
}

// What VTK writes in its own way (NaN skipped from ranges, names it makes up, IdType
// attributes, empty ranges) is left to VTK's writer: write() says so before compressing.
TEST(VtkXmlPiece, LeavesToVtkWhatOnlyVtkWritesExactly) {
  const auto levels = test::sample_frame(0);
  auto refused = [&](auto&& spoil) {
    auto grid = make_level_grid(levels[0].view(), 0.0);
    spoil(grid.GetPointer());
    FrameCompressor compressor(FrameCompression::Lz4);
    VtkXmlPiece piece;
    std::string out;
    const bool written = piece.write(grid, compressor.get(), out);
    if (!written) {  // refused before anything was compressed
      EXPECT_EQ(compressor.blocks().compressed() + compressor.blocks().reused(), 0u);
    }
    return !written;
  };
  EXPECT_FALSE(refused([](vtkUnstructuredGrid*) {}));
  EXPECT_TRUE(refused([](vtkUnstructuredGrid* g) {
    vtkDataArray* u = g->GetPointData()->GetArray("criterion");
    u->SetComponent(3, 0, std::numeric_limits<double>::quiet_NaN());
  }));
  EXPECT_TRUE(refused([](vtkUnstructuredGrid* g) {
    vtkDataArray* u = g->GetPointData()->GetArray("velocity");
    u->SetComponent(0, 2, std::numeric_limits<double>::infinity());
  }));
  EXPECT_TRUE(refused([](vtkUnstructuredGrid* g) {
    auto empty = vtkSmartPointer<vtkDoubleArray>::New();
    empty->SetName("empty");
    g->GetFieldData()->AddArray(empty);
  }));
  EXPECT_TRUE(refused([](vtkUnstructuredGrid* g) {
    auto ids = vtkSmartPointer<vtkIdTypeArray>::New();
    ids->SetName("ids");
    ids->SetNumberOfTuples(g->GetNumberOfPoints());
    ids->FillValue(1);
    g->GetPointData()->AddArray(ids);
  }));
  EXPECT_TRUE(refused([](vtkUnstructuredGrid* g) {
    auto unnamed = vtkSmartPointer<vtkIntArray>::New();
    unnamed->SetNumberOfTuples(g->GetNumberOfPoints());
    unnamed->FillValue(1);
    g->GetPointData()->AddArray(unnamed);
  }));
}

}  // namespace
}  // namespace mrsim
