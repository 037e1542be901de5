// VtkSeriesWriter: frames/frame_NNNNNN.vtm + frames.pvd, read back with VTK's own readers.
#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <sys/stat.h>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <vtkErrorCode.h>

#include "core/error.hpp"
#include "io/vtk_error_capture.hpp"
#include "io/vtk_series_writer.hpp"
#include "io/vtk_tetra_cells.hpp"
#include "vtk_read_checks.hpp"
#include "sample_frames.hpp"
#include "temp_dir.hpp"

namespace mrsim {
namespace {

using test::expect_scalars;
using test::expect_vectors;
using test::kSampleTimes;
using test::read_vtm;
using test::SampleLevel;

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every value of attribute `name` in `xml`, in order.
std::vector<std::string> attribute_values(const std::string& xml, const std::string& name) {
  const std::regex pattern(" " + name + "=\"([^\"]*)\"");
  std::vector<std::string> values;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), pattern);
       it != std::sregex_iterator(); ++it) {
    values.push_back((*it)[1].str());
  }
  return values;
}

void write_three_frames(const std::filesystem::path& dir,
                        FrameCompression compression = FrameCompression::Lz4) {
  VtkSeriesWriter writer(dir, compression);
  for (int f = 0; f < 3; ++f) {
    const auto levels = test::sample_frame(f);
    const auto views = test::views_of(levels);
    writer.write_frame(f, kSampleTimes[f], views);
    EXPECT_EQ(writer.frames_written(), f + 1);
  }
}


void expect_level_grid(vtkUnstructuredGrid* grid, const SampleLevel& level, double time) {
  ASSERT_NE(grid, nullptr);
  const std::size_t n = level.mesh.points.size();
  ASSERT_EQ(grid->GetNumberOfPoints(), static_cast<vtkIdType>(n));
  EXPECT_EQ(grid->GetPoints()->GetDataType(), VTK_DOUBLE);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 deformed = level.mesh.points[i] + level.displacement[i];
    double p[3];
    grid->GetPoint(static_cast<vtkIdType>(i), p);
    for (int c = 0; c < 3; ++c) ASSERT_EQ(p[c], deformed[c]) << "point " << i;
  }
  ASSERT_EQ(grid->GetNumberOfCells(), static_cast<vtkIdType>(level.mesh.tets.size()));
  for (vtkIdType t = 0; t < grid->GetNumberOfCells(); ++t) {
    ASSERT_EQ(grid->GetCellType(t), VTK_TETRA);
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    grid->GetCellPoints(t, count, ids);
    ASSERT_EQ(count, 4);
    for (int c = 0; c < 4; ++c) ASSERT_EQ(ids[c], level.mesh.tets[t][c]) << "tet " << t;
  }
  vtkPointData* data = grid->GetPointData();
  EXPECT_EQ(data->GetNumberOfArrays(), 7);
  expect_vectors(data, "displacement", level.displacement);
  expect_vectors(data, "velocity", level.velocity);
  expect_vectors(data, "force", level.force);
  expect_scalars(data, "status", VTK_SIGNED_CHAR, level.status);
  expect_scalars(data, "time_level", VTK_INT, level.time_level);
  expect_scalars(data, "criterion", VTK_DOUBLE, level.criterion);
  expect_scalars(data, "mass", VTK_DOUBLE, level.mass);
  vtkDataArray* time_value = grid->GetFieldData()->GetArray("TimeValue");
  ASSERT_NE(time_value, nullptr);
  EXPECT_EQ(time_value->GetComponent(0, 0), time);
}

TEST(VtkSeriesWriter, WritesOneMultiblockPerFrameWithNamedLevelBlocks) {
  test::TempDir dir;
  write_three_frames(dir.path());
  for (int f = 0; f < 3; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.vtm", f);
    const auto file = dir.path() / "frames" / name;
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    auto blocks = read_vtm(file);
    ASSERT_NE(blocks, nullptr);
    ASSERT_EQ(blocks->GetNumberOfBlocks(), 2u);
    const auto expected = test::sample_frame(f);
    for (unsigned k = 0; k < 2; ++k) {
      ASSERT_TRUE(blocks->HasMetaData(k));
      EXPECT_STREQ(blocks->GetMetaData(k)->Get(vtkCompositeDataSet::NAME()),
                   ("level_" + std::to_string(k)).c_str());
      expect_level_grid(vtkUnstructuredGrid::SafeDownCast(blocks->GetBlock(k)), expected[k],
                        kSampleTimes[f]);
    }
  }
}

// Frames are staged in frames/.partial, made once and empty between frames (no inode made and
// removed per frame); a finished series leaves no staging folder and nothing under it.
TEST(VtkSeriesWriter, StagesFramesInOneFolderThatTheFinishedSeriesRemoves) {
  test::TempDir dir;
  const auto staging = dir.path() / "frames" / ".partial";
  {
    VtkSeriesWriter writer(dir.path());
    ino_t inode = 0;
    for (int f = 0; f < 3; ++f) {
      const auto levels = test::sample_frame(f);
      writer.write_frame(f, kSampleTimes[f], test::views_of(levels));
      ASSERT_TRUE(std::filesystem::is_directory(staging)) << "after frame " << f;
      EXPECT_TRUE(std::filesystem::is_empty(staging)) << "after frame " << f;
      struct stat st {};
      ASSERT_EQ(::stat(staging.c_str(), &st), 0);
      if (f > 0) {
        EXPECT_EQ(st.st_ino, inode) << "frame " << f << " made the folder again";
      }
      inode = st.st_ino;
    }
  }
  EXPECT_FALSE(std::filesystem::exists(staging));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "frames" / "frame_000001.vtm"));
}

// The writer keeps each block's grid from frame to frame (io/vtk_level_grid.hpp); a block whose
// mesh is another one in the next frame gets that mesh's cells.
TEST(VtkSeriesWriter, ABlockWhoseMeshChangesGetsTheNewCells) {
  test::TempDir dir;
  VtkSeriesWriter writer(dir.path());
  const auto first = test::sample_frame(0);
  writer.write_frame(0, kSampleTimes[0], test::views_of(first));
  const auto second = test::sample_frame(1);
  const std::vector<LevelFrameView> swapped{second[1].view(), second[0].view()};
  writer.write_frame(1, kSampleTimes[1], swapped);
  auto blocks = read_vtm(dir.path() / "frames" / "frame_000001.vtm");
  ASSERT_NE(blocks, nullptr);
  ASSERT_EQ(blocks->GetNumberOfBlocks(), 2u);
  for (unsigned k = 0; k < 2; ++k)
    expect_level_grid(vtkUnstructuredGrid::SafeDownCast(blocks->GetBlock(k)), second[1 - k],
                      kSampleTimes[1]);
}

// Each compression the scenario can ask for (output.compression) is what the pieces declare,
// and VTK's reader gives the frame back exactly.
class VtkCompression
    : public ::testing::TestWithParam<std::pair<FrameCompression, const char*>> {};

TEST_P(VtkCompression, PiecesAreCompressedAsAskedBinaryAndReadableAlone) {
  const auto [compression, compressor] = GetParam();
  test::TempDir dir;
  write_three_frames(dir.path(), compression);
  const auto vtm = dir.path() / "frames" / "frame_000002.vtm";
  const auto pieces = attribute_values(read_text(vtm), "file");
  ASSERT_EQ(pieces.size(), 2u);
  const auto expected = test::sample_frame(2);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const auto piece = vtm.parent_path() / pieces[k];
    const std::string xml = read_text(piece);
    const std::size_t at = xml.find("compressor=");
    if (*compressor == '\0')
      EXPECT_EQ(at, std::string::npos) << piece;
    else
      EXPECT_EQ(xml.substr(at, xml.find('"', at + 12) + 1 - at),
                std::string("compressor=\"") + compressor + "\"")
          << piece;
    EXPECT_NE(xml.find("format=\"appended\""), std::string::npos) << piece;
    EXPECT_NE(xml.find("type=\"Int8\" Name=\"status\""), std::string::npos) << piece;
    // 32-bit cells: half the bytes of VTK's 64-bit ids to compress and write.
    EXPECT_NE(xml.find("type=\"Int32\" Name=\"connectivity\""), std::string::npos) << piece;
    EXPECT_NE(xml.find("type=\"Int32\" Name=\"offsets\""), std::string::npos) << piece;
    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    reader->SetFileName(piece.c_str());
    reader->Update();
    expect_level_grid(reader->GetOutput(), expected[k], kSampleTimes[2]);
  }
}

INSTANTIATE_TEST_SUITE_P(
    VtkSeriesWriter, VtkCompression,
    ::testing::Values(std::pair{FrameCompression::Lz4, "vtkLZ4DataCompressor"},
                      std::pair{FrameCompression::Zlib, "vtkZLibDataCompressor"},
                      std::pair{FrameCompression::None, ""}),
    [](const auto& info) {
      return std::string(info.param.second[0] ? info.param.second + 3 : "None");
    });

// Each piece is written to memory and then to its file at once (no seek and flush per array),
// with the layout and bytes of VTK's own multiblock writer: the frame read back and written again
// by vtkXMLMultiBlockDataWriter, with the same settings, gives the same .vtm and pieces.
TEST_P(VtkCompression, FramesAreTheBytesOfVtksMultiblockWriter) {
  const auto [compression, compressor] = GetParam();
  test::TempDir dir;
  write_three_frames(dir.path(), compression);
  const auto ours = dir.path() / "frames" / "frame_000001.vtm";
  const auto theirs = dir.path() / "again" / "frame_000001.vtm";
  std::filesystem::create_directories(theirs.parent_path());
  auto writer = vtkSmartPointer<vtkXMLMultiBlockDataWriter>::New();
  writer->SetFileName(theirs.c_str());
  writer->SetInputData(read_vtm(ours));
  if (compression == FrameCompression::Lz4) writer->SetCompressorTypeToLZ4();
  if (compression == FrameCompression::Zlib) {
    writer->SetCompressorTypeToZLib();
    writer->SetCompressionLevel(1);
  }
  if (compression == FrameCompression::None) writer->SetCompressorTypeToNone();
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetHeaderTypeToUInt64();
  ASSERT_EQ(writer->Write(), 1);
  EXPECT_EQ(read_text(ours), read_text(theirs));
  const auto pieces = attribute_values(read_text(ours), "file");
  ASSERT_EQ(pieces.size(), 2u);
  for (const std::string& piece : pieces)
    EXPECT_EQ(read_text(ours.parent_path() / piece), read_text(theirs.parent_path() / piece))
        << piece << " (" << compressor << ")";
}

// The cells do not change from frame to frame: from the second frame on, their blocks are not
// compressed again (the bytes are still VTK's: FramesAreTheBytesOfVtksMultiblockWriter).
TEST(VtkSeriesWriter, UnchangedBlocksAreNotCompressedAgain) {
  test::TempDir dir;
  VtkSeriesWriter writer(dir.path());
  std::size_t reused = 0;
  for (int f = 0; f < 3; ++f) {
    const auto levels = test::sample_frame(f);
    writer.write_frame(f, kSampleTimes[f], test::views_of(levels));
    if (f == 0) {
      EXPECT_EQ(writer.reused_blocks(), 0u);
    } else {  // connectivity, offsets and types of both levels at least
      EXPECT_GE(writer.reused_blocks(), reused + 6) << "frame " << f;
    }
    reused = writer.reused_blocks();
  }
  test::TempDir plain;
  VtkSeriesWriter uncompressed(plain.path(), FrameCompression::None);
  const auto levels = test::sample_frame(0);
  uncompressed.write_frame(0, kSampleTimes[0], test::views_of(levels));
  uncompressed.write_frame(1, kSampleTimes[1], test::views_of(levels));
  EXPECT_EQ(uncompressed.reused_blocks(), 0u);
}

TEST(VtkSeriesWriter, PvdListsEveryFrameWithExactTimes) {
  test::TempDir dir;
  write_three_frames(dir.path());
  const std::string pvd = read_text(dir.path() / "frames.pvd");
  EXPECT_NE(pvd.find("type=\"Collection\""), std::string::npos);
  const auto times = attribute_values(pvd, "timestep");
  const auto files = attribute_values(pvd, "file");
  ASSERT_EQ(times.size(), 3u);
  ASSERT_EQ(files.size(), 3u);
  for (int f = 0; f < 3; ++f) {
    EXPECT_EQ(std::strtod(times[f].c_str(), nullptr), kSampleTimes[f]) << times[f];
    char name[40];
    std::snprintf(name, sizeof name, "frames/frame_%06d.vtm", f);
    EXPECT_EQ(files[f], name);
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "frames.pvd.tmp"));
}

TEST(VtkSeriesWriter, PvdIsValidAfterEveryFrame) {
  test::TempDir dir;
  VtkSeriesWriter writer(dir.path());
  for (int f = 0; f < 3; ++f) {
    const auto levels = test::sample_frame(f);
    writer.write_frame(f, kSampleTimes[f], test::views_of(levels));
    // What a run killed right now would leave: a complete collection of the frames so far.
    const std::string pvd = read_text(dir.path() / "frames.pvd");
    EXPECT_EQ(attribute_values(pvd, "timestep").size(), static_cast<std::size_t>(f + 1));
    EXPECT_NE(pvd.find("</VTKFile>"), std::string::npos);
  }
}

TEST(VtkErrorCodeText, SystemCodesInTheSystemsWordsVtkCodesInOurs) {
  // Issue 18 defect 2: a full disk during a frame said "VTK error code 28".
  EXPECT_EQ(vtk_error_code_text(28), "No space left on device (errno 28)");
  EXPECT_EQ(vtk_error_code_text(27), "File too large (errno 27)");
  EXPECT_EQ(vtk_error_code_text(vtkErrorCode::OutOfDiskSpaceError), "out of disk space");
  EXPECT_EQ(vtk_error_code_text(vtkErrorCode::UserError + 5),
            "VTK error code " + std::to_string(vtkErrorCode::UserError + 5));
}

TEST(VtkSeriesWriter, UnusableOutputFolderThrowsRunErrorNamingIt) {
  test::TempDir dir;
  // A regular file where a folder is expected fails even for root (permissions would not).
  const auto blocker = dir.path() / "not_a_folder";
  std::ofstream(blocker) << "x";
  try {
    VtkSeriesWriter writer(blocker / "out");
    FAIL() << "expected RunError";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("not_a_folder"), std::string::npos) << e.what();
  }
}

TEST(VtkSeriesWriter, FrameWriteFailureThrowsRunErrorNamingTheFile) {
  test::TempDir dir;
  VtkSeriesWriter writer(dir.path());
  // The frames folder disappears under the run and a file takes its place.
  std::filesystem::remove_all(dir.path() / "frames");
  std::ofstream(dir.path() / "frames") << "x";
  const auto levels = test::sample_frame(0);
  try {
    writer.write_frame(0, 0.0, test::views_of(levels));
    FAIL() << "expected RunError";
  } catch (const RunError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("frame_000000.vtm"), std::string::npos) << message;
    // VTK's own diagnosis is carried over, without its source-file noise.
    EXPECT_NE(message.find("Not a directory"), std::string::npos) << message;
    EXPECT_EQ(message.find("0x"), std::string::npos) << message;
  }
  EXPECT_EQ(writer.frames_written(), 0);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "frames.pvd"));
}

TEST(VtkSeriesWriter, PvdWriteFailureThrowsRunError) {
  test::TempDir dir;
  VtkSeriesWriter writer(dir.path());
  std::filesystem::create_directories(dir.path() / "frames.pvd.spare");  // cannot be opened as a file
  const auto levels = test::sample_frame(0);
  EXPECT_THROW(writer.write_frame(0, 0.0, test::views_of(levels)), RunError);
}

TEST(VtkSeriesWriter, RejectsArraysOfTheWrongSize) {
  test::TempDir dir;
  VtkSeriesWriter writer(dir.path());
  auto levels = test::sample_frame(0);
  levels[1].mass.pop_back();
  try {
    writer.write_frame(0, 0.0, test::views_of(levels));
    FAIL() << "expected invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("level_1: mass"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mrsim

namespace mrsim {
namespace {

// Cells whose indices fit 32 bits are stored in 32 bits; a mesh with more points than that
// (or more connectivity entries) keeps VTK's 64-bit ids, with the same cells, as do cells asked
// wide.
TEST(UniformCells, ThirtyTwoBitsWhenEveryIndexFitsElseSixtyFour) {
  const std::array<std::array<vtkIdType, 3>, 2> corners{{{0, 1, 2}, {2, 1, 3000000000}}};
  auto corner = [&](vtkIdType c, int k) { return corners[c][k]; };
  const auto small = uniform_cells<3>(1, 3, corner);
  EXPECT_FALSE(small->IsStorage64Bit());
  const auto large = uniform_cells<3>(2, 3000000001, corner);
  EXPECT_TRUE(large->IsStorage64Bit());
  const auto wide = uniform_cells<3>(1, 3, corner, CellIds::Wide);  // `mrsim mesh`'s level files
  EXPECT_TRUE(wide->IsStorage64Bit());
  for (const auto& cells : {small, large, wide}) {
    for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c) {
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      cells->GetCellAtId(c, n, ids);
      ASSERT_EQ(n, 3);
      for (int k = 0; k < 3; ++k) EXPECT_EQ(ids[k], corners[c][k]);
    }
  }
}

}  // namespace
}  // namespace mrsim
