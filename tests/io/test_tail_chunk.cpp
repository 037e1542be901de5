// TailChunk and ZlibDeflater: ExtendibleDataset's numbers written straight into their chunk
// (io/tail_chunk.hpp) must leave the file HDF5's own H5Dwrite() leaves, deflated chunks
// included, whatever happened to the dataset before (reopened, cut back, written converted).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <zlib.h>

#include "h5_reader.hpp"
#include "io/extendible_dataset.hpp"
#include "io/hdf5_error.hpp"
#include "io/zlib_deflater.hpp"
#include "temp_dir.hpp"

namespace mrsim {
namespace {

using h5::ExtendibleDataset;
using h5::ExtendibleSpec;
using test::H5Id;

// A status-like row: runs of equal values, as a level's statuses are.
std::vector<std::int8_t> status_row(int frame, std::size_t points) {
  std::vector<std::int8_t> row(points);
  for (std::size_t p = 0; p < points; ++p)
    row[p] = static_cast<std::int8_t>((p / 97 + static_cast<std::size_t>(frame)) % 3);
  return row;
}

ExtendibleSpec status_spec(std::size_t points, int deflate) {
  ExtendibleSpec spec;
  spec.name = "status";
  spec.file_type = H5T_STD_I8LE;
  spec.row_shape = {points};
  spec.chunk_rows = 1;
  spec.deflate_level = deflate;
  return spec;
}

// The stored bytes of chunk `row` (its filters applied) of a dataset chunked by rows.
std::vector<unsigned char> stored_chunk(hid_t dataset, hsize_t row, std::size_t rank) {
  std::vector<hsize_t> offset(rank, 0);
  offset[0] = row;
  hsize_t bytes = 0;
  EXPECT_GE(H5Dget_chunk_storage_size(dataset, offset.data(), &bytes), 0);
  std::vector<unsigned char> out(bytes);
  std::uint32_t filters = 0;
  EXPECT_GE(H5Dread_chunk(dataset, H5P_DEFAULT, offset.data(), &filters, out.data()), 0);
  EXPECT_EQ(filters, 0u);  // every filter applied
  return out;
}

// The dataset holds status_row(f) for each of its `frames` rows, as written.
void expect_status_rows(hid_t file, const char* path, int frames, std::size_t points) {
  const auto back = test::read_array<std::int8_t>(file, path);
  ASSERT_EQ(back.dims, (std::vector<hsize_t>{static_cast<hsize_t>(frames), points}));
  for (int f = 0; f < frames; ++f)
    EXPECT_TRUE(std::equal(back.values.begin() + f * points,
                           back.values.begin() + (f + 1) * points, status_row(f, points).begin()))
        << "frame " << f;
}

TEST(ZlibDeflater, GivesCompress2sBytesStreamAfterStream) {
  h5::ZlibDeflater deflater(4);
  for (int frame = 0; frame < 5; ++frame) {
    const auto row = status_row(frame, 3386);
    const auto* bytes = reinterpret_cast<const unsigned char*>(row.data());
    std::vector<unsigned char> expected(compressBound(row.size()));
    uLongf size = expected.size();
    ASSERT_EQ(compress2(expected.data(), &size, bytes, row.size(), 4), Z_OK);
    expected.resize(size);
    const auto got = deflater.compress({bytes, row.size()});
    EXPECT_EQ(std::vector<unsigned char>(got.begin(), got.end()), expected) << "frame " << frame;
  }
}

// A row equal to the last one gives its stream again (not deflated anew); a row changed in the
// same buffer, or one of another length, is deflated: each is compress2()'s stream of its bytes.
TEST(ZlibDeflater, RepeatedRowsGiveTheirStreamAndChangedRowsANewOne) {
  const auto bytes = [](const std::vector<std::int8_t>& row) {
    return std::span<const unsigned char>(reinterpret_cast<const unsigned char*>(row.data()),
                                          row.size());
  };
  const auto stream = [&](h5::ZlibDeflater& deflater, const std::vector<std::int8_t>& row) {
    const auto got = deflater.compress(bytes(row));
    return std::vector<unsigned char>(got.begin(), got.end());
  };
  const auto fresh = [&](const std::vector<std::int8_t>& row) {
    h5::ZlibDeflater once(4, Z_RLE);
    return stream(once, row);
  };
  h5::ZlibDeflater deflater(4, Z_RLE);
  std::vector<std::int8_t> row = status_row(0, 3386);
  const std::vector<unsigned char> first = stream(deflater, row);
  EXPECT_EQ(first, fresh(row));
  EXPECT_EQ(stream(deflater, row), first);  // the same bytes again
  row[1700] = static_cast<std::int8_t>(row[1700] + 1);  // one status changed, same buffer
  EXPECT_EQ(stream(deflater, row), fresh(row));
  EXPECT_NE(stream(deflater, row), first);
  row.pop_back();  // a shorter row whose bytes are a prefix of the last one
  EXPECT_EQ(stream(deflater, row), fresh(row));
}

// The deflated status rows of a fine level: each chunk's stored bytes are those HDF5's deflate
// filter stores through H5Dwrite(), and they read back as written.
TEST(TailChunk, DeflatedRowsAreTheChunksHdf5Writes) {
  test::TempDir dir;
  const auto ours = dir.path() / "ours.h5", theirs = dir.path() / "theirs.h5";
  constexpr std::size_t kPoints = 3386;
  constexpr int kFrames = 6;
  {
    h5::silence_automatic_error_printing();
    H5Id file(H5Fcreate(ours.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    ExtendibleDataset status(file, "/", status_spec(kPoints, 4), ours.string());
    for (int f = 0; f < kFrames; ++f) {
      const auto row = status_row(f, kPoints);
      status.append(std::span<const std::int8_t>(row));
    }
    status.close();
  }
  {  // the same rows through HDF5's filter pipeline
    H5Id file(H5Fcreate(theirs.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    const hsize_t dims[2] = {kFrames, kPoints}, chunk[2] = {1, kPoints};
    H5Id space(H5Screate_simple(2, dims, nullptr), H5Sclose);
    H5Id dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    H5Pset_chunk(dcpl, 2, chunk);
    H5Pset_deflate(dcpl, 4);
    H5Id status(H5Dcreate2(file, "status", H5T_STD_I8LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
                H5Dclose);
    std::vector<std::int8_t> all;
    for (int f = 0; f < kFrames; ++f) {
      const auto row = status_row(f, kPoints);
      all.insert(all.end(), row.begin(), row.end());
    }
    ASSERT_GE(H5Dwrite(status, H5T_NATIVE_INT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, all.data()), 0);
  }
  H5Id a(test::open_read_only(ours), H5Fclose), b(test::open_read_only(theirs), H5Fclose);
  H5Id da(H5Dopen2(a, "/status", H5P_DEFAULT), H5Dclose), db(H5Dopen2(b, "/status", H5P_DEFAULT),
                                                               H5Dclose);
  for (hsize_t f = 0; f < kFrames; ++f) {
    const auto mine = stored_chunk(da, f, 2);
    EXPECT_LT(mine.size(), kPoints / 4) << "frame " << f << " is not compressed";
    EXPECT_EQ(mine, stored_chunk(db, f, 2)) << "frame " << f;
  }
  expect_status_rows(a, "/status", kFrames, kPoints);
}

// The status rows of log.h5 are deflated with zlib's run-length strategy: HDF5 reads them back
// as written, and runs of equal statuses take no more room than at the default strategy.
TEST(TailChunk, RunLengthDeflatedRowsReadBackAndAreNoLarger) {
  test::TempDir dir;
  const auto path = dir.path() / "t.h5";
  constexpr std::size_t kPoints = 3386;
  constexpr int kFrames = 4;
  {
    H5Id file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    ExtendibleSpec runs = status_spec(kPoints, 4), plain = status_spec(kPoints, 4);
    runs.deflate_runs = true;
    plain.name = "plain";
    ExtendibleDataset a(file, "/", runs, path.string()), b(file, "/", plain, path.string());
    for (int f = 0; f < kFrames; ++f) {
      const auto row = status_row(f, kPoints);
      a.append(std::span<const std::int8_t>(row));
      b.append(std::span<const std::int8_t>(row));
    }
  }
  H5Id file(test::open_read_only(path), H5Fclose);
  H5Id runs(H5Dopen2(file, "/status", H5P_DEFAULT), H5Dclose),
      plain(H5Dopen2(file, "/plain", H5P_DEFAULT), H5Dclose);
  for (hsize_t f = 0; f < kFrames; ++f) {
    const auto r = stored_chunk(runs, f, 2), p = stored_chunk(plain, f, 2);
    EXPECT_NE(r, p) << "frame " << f << ": not the run-length strategy's stream";
    EXPECT_LE(r.size(), p.size()) << "frame " << f;
  }
  expect_status_rows(file, "/status", kFrames, kPoints);
}

ExtendibleSpec row_spec(hid_t file_type) {
  ExtendibleSpec spec;
  spec.name = "values";
  spec.file_type = file_type;
  spec.row_shape = {2};
  spec.chunk_rows = 4;
  return spec;
}

// A resumed run reopens the log, cuts it back to its checkpoint and appends into the middle of
// a chunk: the rows kept before the cut must stay, the cut ones must not come back.
TEST(TailChunk, RowsKeptBeforeACutStayWhenAppendingAfterReopening) {
  test::TempDir dir;
  const auto path = dir.path() / "t.h5";
  std::vector<double> values;
  for (int i = 0; i < 2 * 7; ++i) values.push_back(1.5 * i);
  {
    H5Id file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    ExtendibleDataset d(file, "/", row_spec(H5T_IEEE_F64LE), path.string());
    d.append(std::span<const double>(values).first(2 * 6));  // rows 0..5: chunk 1 half full
    d.close();
  }
  {
    H5Id file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
    ExtendibleDataset d(file, "/", row_spec(H5T_IEEE_F64LE), path.string(),
                        ExtendibleDataset::Mode::Reopen);
    ASSERT_EQ(d.rows(), 6u);
    d.truncate(5);
    const std::vector<double> more = {-1, -2, -3, -4};
    d.append(std::span<const double>(more));  // rows 5, 6
    d.close();
  }
  H5Id file(test::open_read_only(path), H5Fclose);
  const auto back = test::read_array<double>(file, "/values");
  ASSERT_EQ(back.dims, (std::vector<hsize_t>{7, 2}));
  std::vector<double> expected(values.begin(), values.begin() + 10);
  expected.insert(expected.end(), {-1, -2, -3, -4});
  EXPECT_EQ(back.values, expected);
}

// Rows HDF5 converted (doubles stored as floats) and rows written straight share a chunk.
TEST(TailChunk, ConvertedAndStraightRowsShareAChunk) {
  test::TempDir dir;
  const auto path = dir.path() / "t.h5";
  {
    H5Id file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    ExtendibleDataset d(file, "/", row_spec(H5T_IEEE_F32LE), path.string());
    const std::vector<float> straight = {1, 2, 3, 4};
    const std::vector<double> converted = {5, 6};
    d.append(straight.data(), H5T_NATIVE_FLOAT, 2);  // rows 0, 1: straight
    d.append(std::span<const double>(converted));     // row 2: converted by HDF5
    d.append(straight.data(), H5T_NATIVE_FLOAT, 2);  // rows 3, 4: straight, over two chunks
    d.close();
  }
  H5Id file(test::open_read_only(path), H5Fclose);
  const auto back = test::read_array<double>(file, "/values");
  EXPECT_EQ(back.values, (std::vector<double>{1, 2, 3, 4, 5, 6, 1, 2, 3, 4}));
}

}  // namespace
}  // namespace mrsim
