// The VTK series: a frame's blocks read into arrays, differences named by frame, block, array
// and point, capped per series; missing or truncated pieces are input errors naming them.
#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataWriter.h>

#include <fstream>
#include <sstream>

#include "compare/compare_report.hpp"
#include "compare/frames_diff.hpp"
#include "compare/vtm_frames.hpp"
#include "core/error.hpp"
#include "io/temp_dir.hpp"

namespace mrsim {
namespace {

namespace fs = std::filesystem;

vtkSmartPointer<vtkUnstructuredGrid> tet_grid(double shift) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p :
       {std::array{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}) {
    points->InsertNextPoint(p.data());
  }
  grid->SetPoints(points);
  const vtkIdType tet[4] = {0, 1, 2, 3};
  grid->InsertNextCell(VTK_TETRA, 4, tet);
  vtkNew<vtkDoubleArray> displacement;
  displacement->SetName("displacement");
  displacement->SetNumberOfComponents(3);
  for (int i = 0; i < 4; ++i) displacement->InsertNextTuple3(0.001 * i, 0.0, i == 2 ? shift : 0.0);
  grid->GetPointData()->AddArray(displacement);
  vtkNew<vtkSignedCharArray> status;
  status->SetName("status");
  for (int i = 0; i < 4; ++i) status->InsertNextValue(2);
  grid->GetPointData()->AddArray(status);
  return grid;
}

vtkSmartPointer<vtkPolyData> triangle() {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  poly->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  const vtkIdType ids[3] = {0, 1, 2};
  polys->InsertNextCell(3, ids);
  poly->SetPolys(polys);
  vtkNew<vtkIntArray> owner;
  owner->SetName("tool");
  owner->InsertNextValue(0);
  poly->GetCellData()->AddArray(owner);
  return poly;
}

// A run folder with frames.pvd and `frames` frames; frame k's level block has
// displacement z of point 2 = shift(k).
template <class Shift>
void write_run(const fs::path& run, int frames, Shift shift) {
  fs::create_directories(run / "frames");
  std::ofstream pvd(run / "frames.pvd");
  pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (int k = 0; k < frames; ++k) {
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(2);
    blocks->SetBlock(0, tet_grid(shift(k)));
    blocks->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "level_0");
    blocks->SetBlock(1, triangle());
    blocks->GetMetaData(1u)->Set(vtkCompositeDataSet::NAME(), "surface");
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.vtm", k);
    vtkNew<vtkXMLMultiBlockDataWriter> writer;
    writer->SetFileName((run / "frames" / name).c_str());
    writer->SetInputData(blocks);
    if (writer->Write() == 0) throw std::runtime_error("cannot write the frame");
    pvd << "<DataSet timestep=\"" << 0.02 * k << "\" group=\"\" part=\"0\" file=\"frames/" << name
        << "\"/>\n";
  }
  pvd << "</Collection>\n</VTKFile>\n";
}

TEST(VtmFrames, ReadsBlocksPointsCellsAndArrays) {
  test::TempDir dir;
  write_run(dir.path(), 1, [](int) { return 0.0; });
  const std::vector<FrameBlock> blocks = read_vtm_frame(dir.path() / "frames" / "frame_000000.vtm");
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].name, "level_0");
  EXPECT_EQ(blocks[0].type, "vtkUnstructuredGrid");
  EXPECT_EQ(blocks[0].points, 4u);
  EXPECT_EQ(blocks[1].name, "surface");
  std::vector<std::string> labels;
  for (const BlockArray& a : blocks[0].arrays) labels.push_back(a.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"points", "cell types", "cell connectivity",
                                              "point array displacement", "point array status"}));
  EXPECT_EQ(blocks[0].arrays[2].values.shape, (Shape{1, 4}));
  EXPECT_EQ(blocks[0].arrays[4].values.kind, ValueKind::Integer);
  EXPECT_EQ(blocks[0].arrays[3].values.shape, (Shape{4, 3}));
  EXPECT_EQ(blocks[1].arrays.back().label, "cell array tool");
}

TEST(VtmFrames, NamesFrameBlockArrayAndPoint) {
  test::TempDir dir;
  write_run(dir.path() / "a", 3, [](int) { return 0.0; });
  write_run(dir.path() / "b", 3, [](int k) { return k == 2 ? 1e-3 : 0.0; });
  CompareReport report("a", "b");
  diff_frames(dir.path() / "a", dir.path() / "b", {}, report);
  ASSERT_EQ(report.lines().size(), 1u);
  EXPECT_EQ(report.lines()[0].subject,
            "frame 2 (t = 0.04 s) block level_0 point array displacement [4×3]");
  EXPECT_EQ(report.lines()[0].detail,
            "1 of 12 values differ; max abs 0.001 at point 2 component 2 (A 0, B 0.001); "
            "max rel 1 at point 2 component 2");
  CompareReport loose("a", "b");
  diff_frames(dir.path() / "a", dir.path() / "b", {0, 2e-3}, loose);
  EXPECT_TRUE(loose.identical());
}

TEST(VtmFrames, CapsTheFramesReportedPerSeries) {
  test::TempDir dir;
  const int frames = CompareReport::kFramesPerSeries + 5;
  write_run(dir.path() / "a", frames, [](int) { return 0.0; });
  write_run(dir.path() / "b", frames, [](int k) { return 1e-3 * (k + 1); });
  CompareReport report("a", "b");
  diff_frames(dir.path() / "a", dir.path() / "b", {}, report);
  EXPECT_EQ(report.lines().size(), CompareReport::kFramesPerSeries);
  EXPECT_EQ(report.differing(Section::Frames), static_cast<std::size_t>(frames));
  std::ostringstream out;
  report.print(out, {});
  EXPECT_NE(out.str().find("block level_0 point array displacement: and 5 more frames differ"),
            std::string::npos)
      << out.str();
}

TEST(VtmFrames, FrameListsMustMatch) {
  test::TempDir dir;
  write_run(dir.path() / "a", 3, [](int) { return 0.0; });
  write_run(dir.path() / "b", 2, [](int) { return 0.0; });
  CompareReport report("a", "b");
  diff_frames(dir.path() / "a", dir.path() / "b", {}, report);
  ASSERT_EQ(report.lines().size(), 1u);
  EXPECT_EQ(report.lines()[0].detail, "A lists 3 frames, B 2; the first 2 are compared");
  fs::remove(dir.path() / "b" / "frames.pvd");
  CompareReport one_side("a", "b");
  diff_frames(dir.path() / "a", dir.path() / "b", {}, one_side);
  ASSERT_EQ(one_side.lines().size(), 1u);
  EXPECT_EQ(one_side.lines()[0].detail, "only in A");
}

void expect_input_error_naming(const fs::path& vtm, const std::string& file) {
  try {
    read_vtm_frame(vtm);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
  }
}

TEST(VtmFrames, MissingOrTruncatedPiecesAreInputErrors) {
  test::TempDir dir;
  write_run(dir.path(), 1, [](int) { return 0.0; });
  const fs::path vtm = dir.path() / "frames" / "frame_000000.vtm";
  const fs::path grid = dir.path() / "frames" / "frame_000000" / "frame_000000_0.vtu";
  const fs::path surface = dir.path() / "frames" / "frame_000000" / "frame_000000_1.vtp";
  ASSERT_TRUE(fs::exists(grid) && fs::exists(surface));
  const auto grid_size = fs::file_size(grid);
  const auto surface_size = fs::file_size(surface);
  fs::resize_file(surface, surface_size * 2 / 3);  // no header check for .vtp: VTK's errors
  expect_input_error_naming(vtm, "frame_000000_1.vtp");
  fs::resize_file(surface, 0);
  expect_input_error_naming(vtm, "frame_000000_1.vtp");
  fs::resize_file(grid, grid_size * 2 / 3);
  expect_input_error_naming(vtm, "frame_000000_0.vtu");
  fs::remove(grid);
  expect_input_error_naming(vtm, "frame_000000_0.vtu");
  std::ofstream(vtm) << "<VTKFile type=\"vtkMultiBlockDataSet\"><vtkMultiBlockDataSet>";
  expect_input_error_naming(vtm, "frame_000000.vtm");
}

}  // namespace
}  // namespace mrsim
