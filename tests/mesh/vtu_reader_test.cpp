// VTU reader: what VTK does not check itself (indices, offsets, counts) and how its silent
// failures (empty output, printed errors) become InputErrors.
#include <gtest/gtest.h>

#include "mesh_test_support.hpp"

namespace mrsim::test {
namespace {

struct Cells {
  std::string connectivity, offsets, types;
  int count;
};

// An ascii .vtu as VTK writes it, with the unit tet's 4 points (plus `extra_points`).
std::string vtu_ascii(const Cells& c, int declared_points = 4,
                      const std::string& extra_points = "") {
  return "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt32\">\n"
         "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" +
         std::to_string(declared_points) + "\" NumberOfCells=\"" + std::to_string(c.count) +
         "\">\n"
         "<Points>\n<DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" "
         "format=\"ascii\">\n"
         "0 0 0 1 0 0 0 1 0 0 0 1 " +
         extra_points +
         "\n</DataArray>\n</Points>\n<Cells>\n"
         "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n" +
         c.connectivity +
         "\n</DataArray>\n"
         "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n" +
         c.offsets +
         "\n</DataArray>\n"
         "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n" +
         c.types +
         "\n</DataArray>\n"
         "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

TEST(VtuReader, KeepsTetsAndSkipsLowerDimensionalCells) {
  ScratchDir dir;
  // vertex, line, triangle, tet
  write_file(dir / "m.vtu", vtu_ascii({"0 0 1 0 1 2 0 1 2 3", "1 3 6 10", "1 3 5 10", 4}));
  MeshReadReport report;
  const TetMesh m = read_tet_mesh(dir / "m.vtu", LengthUnit::Metre, &report);
  ASSERT_EQ(m.tets.size(), 1u);
  EXPECT_EQ(m.tets[0], (Tet{0, 1, 2, 3}));
  EXPECT_EQ(report.notes, (std::vector<std::string>{"ignored 1 lines", "ignored 1 triangles",
                                                    "ignored 1 vertex cells"}));
}

TEST(VtuReader, OutOfRangePointIndexIsRejected) {
  ScratchDir dir;
  write_file(dir / "m.vtu", vtu_ascii({"0 1 2 7", "4", "10", 1}));
  expect_mesh_error(dir / "m.vtu", {"cell 0 refers to point 7, but the file has 4 points"});
  write_file(dir / "neg.vtu", vtu_ascii({"0 1 2 -1", "4", "10", 1}));
  expect_mesh_error(dir / "neg.vtu", {"cell 0 refers to point -1"});
}

TEST(VtuReader, OtherVolumeCellsAreRejected) {
  ScratchDir dir;
  write_file(dir / "hex.vtu", vtu_ascii({"0 1 2 3 0 1 2 3", "8", "12", 1}));
  expect_mesh_error(dir / "hex.vtu",
                    {"cell 0: vtkHexahedron cells (VTK cell type 12) are not supported"});
  write_file(dir / "tet10.vtu", vtu_ascii({"0 1 2 3 0 1 2 3 0 1", "10", "24", 1}));
  expect_mesh_error(dir / "tet10.vtu",
                    {"vtkQuadraticTetra cells (VTK cell type 24)", "export linear elements"});
  write_file(dir / "wedge.vtu",
             vtu_ascii({"0 1 2 3 0 1 2 3 0 1 2 3 0 1 2 3 0 1 2 3 0 1 2 3", "6", "13", 1}));
  expect_mesh_error(dir / "wedge.vtu", {"vtkWedge cells (VTK cell type 13)"});
  write_file(dir / "bad.vtu", vtu_ascii({"0 1 2 3", "4", "200", 1}));
  expect_mesh_error(dir / "bad.vtu", {"unknown VTK cell type 200"});
}

TEST(VtuReader, TetraWithWrongPointCountIsRejected) {
  ScratchDir dir;
  write_file(dir / "m.vtu", vtu_ascii({"0 1 2", "3", "10", 1}));
  expect_mesh_error(dir / "m.vtu", {"cell 0 is a tetrahedron with 3 points"});
}

TEST(VtuReader, SurfaceOnlyFileIsRejected) {
  ScratchDir dir;
  write_file(dir / "m.vtu", vtu_ascii({"0 1 2 0 1 3", "3 6", "5 5", 2}));
  expect_mesh_error(dir / "m.vtu",
                    {"contains no tetrahedra (only 2 triangles): a volume mesh is needed"});
}

TEST(VtuReader, InconsistentOffsetsAreRejected) {
  ScratchDir dir;
  write_file(dir / "dec.vtu", vtu_ascii({"0 1 2 3 0 1 2 3", "8 4", "10 10", 2}));
  expect_mesh_error(dir / "dec.vtu", {"offsets"});
  write_file(dir / "short.vtu", vtu_ascii({"0 1 2 3", "4 8", "10 10", 2}));
  expect_mesh_error(dir / "short.vtu", {"connectivity"});
}

TEST(VtuReader, MissingValuesAreRejected) {
  ScratchDir dir;
  // The header promises 5 points but the array holds 4.
  write_file(dir / "pts.vtu", vtu_ascii({"0 1 2 3", "4", "10", 1}, 5));
  expect_mesh_error(dir / "pts.vtu", {"VTK could not read the file"});
  // One cell type for two cells.
  write_file(dir / "types.vtu", vtu_ascii({"0 1 2 3 0 1 2 3", "4 8", "10", 2}));
  expect_mesh_error(dir / "types.vtu", {"VTK could not read the file"});
}

TEST(VtuReader, LyingHeaderCountsAreRejectedBeforeVtkAllocates) {
  ScratchDir dir;
  write_file(dir / "big.vtu", vtu_ascii({"0 1 2 3", "4", "10", 1}, 100000000));
  expect_mesh_error(dir / "big.vtu", {"declares 100000000 points", "bytes can hold"});
  std::string text = vtu_ascii({"0 1 2 3", "4", "10", 1});
  text.replace(text.find("NumberOfCells=\"1\""), 17, "NumberOfCells=\"99999999999\"");
  write_file(dir / "huge.vtu", text);
  expect_mesh_error(dir / "huge.vtu", {"invalid NumberOfCells"});
  // Compressed: zlib can expand ~1000x, not 1e6x.
  std::string zipped = read_file(fixture("box_appended_zlib.vtu"));
  const auto at = zipped.find("NumberOfPoints=\"36\"");
  zipped.replace(at, 19, "NumberOfPoints=\"360000000\"");
  write_file(dir / "zip.vtu", zipped);
  expect_mesh_error(dir / "zip.vtu", {"declares 360000000 points"});
}

// VTK reads NumberOfComponents="\n" as an uninitialised count and churns for a minute.
TEST(VtuReader, InvalidComponentCountIsRejectedBeforeVtk) {
  ScratchDir dir;
  const std::string original = read_file(fixture("box_appended_zlib.vtu"));
  for (const char* bad : {"\n", "0", "-1", "3x", "99999999"}) {
    std::string text = original;
    text.replace(text.find("NumberOfComponents=\"3\""), 22,
                 std::string("NumberOfComponents=\"") + bad + "\"");
    write_file(dir / "m.vtu", text);
    expect_mesh_error(dir / "m.vtu", {"data array 'Points' has an invalid NumberOfComponents"});
  }
}

// VTK takes the first non-blank character after <AppendedData ...> as the '_' marker
// without checking it: a stray byte there shifts every offset by one.
TEST(VtuReader, AppendedDataMustStartWithUnderscore) {
  ScratchDir dir;
  std::string text = read_file(fixture("box_appended_zlib.vtu"));
  const auto marker = text.find('_', text.find("<AppendedData"));
  text[marker - 1] = '0';
  write_file(dir / "m.vtu", text);
  expect_mesh_error(dir / "m.vtu", {"the appended data does not start with '_'"});
}

TEST(VtuReader, LyingCompressionHeaderIsRejected) {
  ScratchDir dir;
  // The first array's zlib header: [nblocks, block size, last block size, compressed sizes].
  // Claim 2^31 blocks (VTK would allocate and clear 8 GB for their sizes), or a 2 GB block,
  // or 2 GB of compressed data.
  std::string zipped = read_file(fixture("box_appended_zlib.vtu"));
  const auto data = zipped.find('_', zipped.find("<AppendedData")) + 1;
  const std::uint32_t lie = 0x7fffffff;
  const char* expected[] = {"announces 2147483647 blocks", "", "uncompressed bytes",
                            "compressed bytes"};
  for (int field : {0, 2, 3}) {
    std::string bad = zipped;
    std::memcpy(bad.data() + data + 4 * field, &lie, 4);
    write_file(dir / "m.vtu", bad);
    expect_mesh_error(dir / "m.vtu", {"compressed data array 'Points'", expected[field]});
  }
}

// Found by the mesh fuzzer (issue 18): zero blocks with a non-zero last block size made VTK
// compute a data size of ~2^64 bytes and read block 0 from an empty block table (SIGSEGV).
TEST(VtuReader, CompressionHeaderWithALastBlockButNoBlocksIsRejected) {
  ScratchDir dir;
  for (const fs::path& file : {fixture("box_appended_zlib.vtu"),  // UInt32 headers
                               source_dir() / "scenarios" / "meshes" / "beam_L0.vtu"}) {  // UInt64
    std::string zipped = read_file(file);
    const auto data = zipped.find('_', zipped.find("<AppendedData")) + 1;
    const auto offsets = zipped.find("offset=\"", zipped.find("Name=\"offsets\"")) + 8;
    const std::size_t at = data + std::stoul(zipped.substr(offsets));  // nblocks of 'offsets'
    ASSERT_EQ(zipped[at], 1);
    zipped[at] = 0;
    write_file(dir / "m.vtu", zipped);
    expect_mesh_error(dir / "m.vtu", {"compressed data array 'offsets' announces a last block of",
                                      "but no blocks"});
  }
}

// The header of the 'offsets' array of box_appended_zlib.vtu with no blocks but a last block
// (the crash above), in a file whose tag for that array is rewritten by `edit`.
std::string zero_blocks_for_offsets(const std::function<void(std::string&)>& edit) {
  std::string zipped = read_file(fixture("box_appended_zlib.vtu"));
  const auto data = zipped.find('_', zipped.find("<AppendedData")) + 1;
  const auto offsets = zipped.find("offset=\"", zipped.find("Name=\"offsets\"")) + 8;
  zipped[data + std::stoul(zipped.substr(offsets))] = 0;
  edit(zipped);
  return zipped;
}

// Found by the mesh fuzzer (issue 18): VTK reads appended data whenever an element has an
// offset, whatever its format says; the checks skipped arrays whose format was not exactly
// "appended", and VTK crashed on their block header.
TEST(VtuReader, ArraysWithAnOffsetAreCheckedWhateverTheirFormat) {
  ScratchDir dir;
  const std::string tag = "Name=\"offsets\" format=\"appended\"";
  for (const std::string& replacement :
       {std::string("Name=\"offsets\" format=\"ascii\""), std::string("Name=\"offsets\""),
        std::string("Name=\"offsets\" format=\"a\xffppended\"")}) {
    write_file(dir / "m.vtu", zero_blocks_for_offsets([&](std::string& text) {
                 text.replace(text.find(tag), tag.size(), replacement);
               }));
    expect_mesh_error(dir / "m.vtu", {"compressed data array 'offsets'", "but no blocks"});
  }
}

// Found by the mesh fuzzer: VTK reads the element inside <Points> whatever it is called, and
// XML allows tabs, newlines and single quotes around attributes. The checks looked for
// `<DataArray` and ` NumberOfComponents="` only, so <DataArrAy ... NumberOfComponents=
// "2147483651"> reached VTK, which looped over 2^31 component names for three minutes.
TEST(VtuReader, ArraysAreCheckedWhateverTheirTagNameAndSpacing) {
  ScratchDir dir;
  const std::string original = read_file(fixture("box_appended_zlib.vtu"));
  const std::string tag = "<DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"";
  for (const char* replacement :
       {"<DataArrAy type=\"Float64\" Name=\"Points\" NumberOfComponents=\"2147483651\"",
        "<Array type=\"Float64\" Name=\"Points\" NumberOfComponents=\"\n\"",
        "<DataArray type=\"Float64\" Name=\"Points\"\tNumberOfComponents = '\n'",
        "<DataArray Note=\"a>b\" type=\"Float64\" Name=\"Points\" NumberOfComponents=\"0\""}) {
    std::string text = original;
    text.replace(text.find(tag), tag.size(), replacement);
    write_file(dir / "m.vtu", text);
    expect_mesh_error(dir / "m.vtu", {"has an invalid NumberOfComponents"});
  }
}

// Expat decodes "&#54;" to "6" before VTK reads header_type="UInt&#54;4"; the checks would
// read 4-byte block headers where VTK reads 8-byte ones. No writer does this: refused.
TEST(VtuReader, XmlReferencesInStructuralAttributesAreRefused) {
  ScratchDir dir;
  std::string text = read_file(fixture("box_appended_zlib.vtu"));
  text.replace(text.find("header_type=\"UInt32\""), 20, "header_type=\"UInt&#51;2\"");
  write_file(dir / "m.vtu", text);
  expect_mesh_error(dir / "m.vtu", {"header_type attribute", "XML reference"});
}

// VTK skips only ' ', '\t', '\n' and '\r' before the appended data's '_'; skipping a '\v' as
// well would check other bytes than the ones VTK reads.
TEST(VtuReader, AppendedDataMarkerIsFoundAsVtkFindsIt) {
  ScratchDir dir;
  std::string text = read_file(fixture("box_appended_zlib.vtu"));
  text[text.find('_', text.find("<AppendedData")) - 1] = '\v';
  write_file(dir / "m.vtu", text);
  expect_mesh_error(dir / "m.vtu", {"the appended data does not start with '_'"});
}

// VTK sizes the connectivity array by the last offset, which only it decodes: a huge one
// makes it ask for petabytes. Release builds get std::bad_alloc (an InputError); under ASan
// this aborted until tests/mesh/sanitizer_suppressions.cpp let malloc return null (mesh fuzzer).
TEST(VtuReader, HugeLastOffsetIsAnInputError) {
  ScratchDir dir;
  for (const char* last : {"99999999999999", "4294967296"}) {
    write_file(dir / "m.vtu", vtu_ascii({"0 1 2 3", last, "10", 1}));
    expect_mesh_error(dir / "m.vtu", {"VTK ran out of memory"});
  }
}

TEST(VtuReader, LyingBase64CompressionHeaderIsRejected) {
  ScratchDir dir;
  // Inline base64 header of the Points array: "AQAAAACA" encodes nblocks = 1 and the first
  // bytes of the block size 32768; "////fwCA" makes nblocks 2^31 - 1.
  std::string text = read_file(fixture("box_inline_zlib.vtu"));
  const auto at = text.find("AQAAAACA", text.find("Name=\"Points\""));
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 8, "////fwCA");
  write_file(dir / "m.vtu", text);
  expect_mesh_error(dir / "m.vtu", {"compressed data array 'Points' announces 2147483647 blocks"});
}

TEST(VtuReader, TruncatedFilesAreRejected) {
  ScratchDir dir;
  const std::string bytes = read_file(fixture("box_appended_zlib.vtu"));
  // Inside the appended binary data, and inside the XML header.
  for (std::size_t length :
       {bytes.size() - 40, bytes.find("<AppendedData") + 60, std::size_t{300}}) {
    write_file(dir / "cut.vtu", bytes.substr(0, length));
    expect_mesh_error(dir / "cut.vtu", {"truncated or corrupt"});
  }
}

TEST(VtuReader, NonVtuContentIsRejected) {
  ScratchDir dir;
  write_file(dir / "text.vtu", "hello\n");
  expect_mesh_error(dir / "text.vtu", {"not a VTK XML file"});
  write_file(dir / "poly.vtu",
             "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\">\n</VTKFile>\n");
  expect_mesh_error(dir / "poly.vtu", {"holds VTK PolyData data"});
  write_file(dir / "broken.vtu",
             "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n<UnstructuredGrid>"
             "<Piece NumberOfPoints=\"0\" NumberOfCells=\"0\"></Piec");
  expect_mesh_error(dir / "broken.vtu", {"VTK could not read the file", "Error parsing XML"});
  write_file(dir / "count.vtu", "<VTKFile type=\"UnstructuredGrid\"><Piece NumberOfPoints=\"x\"");
  expect_mesh_error(dir / "count.vtu", {"invalid NumberOfPoints"});
}

}  // namespace
}  // namespace mrsim::test
