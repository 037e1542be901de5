// ExtendibleDataset, the generic appendable dataset behind /frames, /events and (later) /tool.
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "h5_reader.hpp"
#include "io/extendible_dataset.hpp"
#include "io/hdf5_error.hpp"
#include "io/hdf5_types.hpp"
#include "temp_dir.hpp"

namespace mrsim {
namespace {

using h5::ExtendibleDataset;
using h5::ExtendibleSpec;
using test::H5Id;

ExtendibleSpec vector_spec(hsize_t width) {
  ExtendibleSpec spec;
  spec.name = "position";
  spec.file_type = H5T_IEEE_F64LE;
  spec.row_shape = {width};
  spec.chunk_rows = 4;
  spec.units = std::string(1, 'm');  // not = "m": GCC 12 warns (-Wrestrict, a false positive)
  return spec;
}

TEST(ExtendibleDataset, AppendsBatchesOfRowsAcrossChunkBoundaries) {
  test::TempDir dir;
  const auto path = dir.path() / "t.h5";
  {
    h5::silence_automatic_error_printing();
    H5Id file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    ExtendibleDataset dataset(file, "/", vector_spec(3), path.string());
    std::vector<double> values;
    for (int i = 0; i < 3 * 7; ++i) values.push_back(i / 3.0);
    dataset.append(std::span<const double>(values).first(6));   // 2 rows
    dataset.append(std::span<const double>(values).subspan(6));  // 5 more: spans 2 chunks
    EXPECT_EQ(dataset.rows(), 7u);
    dataset.close();
  }
  H5Id file(test::open_read_only(path), H5Fclose);
  const auto back = test::read_array<double>(file, "/position");
  ASSERT_EQ(back.dims, (std::vector<hsize_t>{7, 3}));
  for (int i = 0; i < 3 * 7; ++i) EXPECT_EQ(back.values[i], i / 3.0);
  H5Id dataset(H5Dopen2(file, "/position", H5P_DEFAULT), H5Dclose);
  EXPECT_EQ(test::read_string_attribute(dataset, "units"), "m");
}

TEST(ExtendibleDataset, RowsOfZeroValuesStillCount) {
  // A level without points still gets one (empty) status row per frame.
  test::TempDir dir;
  const auto path = dir.path() / "t.h5";
  {
    H5Id file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    ExtendibleDataset dataset(file, "/", vector_spec(0), path.string());
    dataset.append(std::span<const double>());
    dataset.append(std::span<const double>());
    EXPECT_EQ(dataset.rows(), 2u);
  }
  H5Id file(test::open_read_only(path), H5Fclose);
  EXPECT_EQ(test::read_array<double>(file, "/position").dims, (std::vector<hsize_t>{2, 0}));
}

TEST(ExtendibleDataset, RejectsPartialRows) {
  test::TempDir dir;
  const auto path = dir.path() / "t.h5";
  H5Id file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  ExtendibleDataset dataset(file, "/", vector_spec(3), path.string());
  const std::vector<double> values(4, 1.0);
  EXPECT_THROW(dataset.append(std::span<const double>(values)), std::invalid_argument);
  EXPECT_EQ(dataset.rows(), 0u);
}

TEST(ExtendibleDataset, DuplicateNameThrowsRunErrorNamingFileAndDataset) {
  test::TempDir dir;
  const auto path = dir.path() / "t.h5";
  H5Id file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  ExtendibleDataset first(file, "/", vector_spec(3), path.string());
  try {
    ExtendibleDataset second(file, "/", vector_spec(3), path.string());
    FAIL() << "expected RunError";
  } catch (const RunError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("t.h5:/position: cannot create dataset"), std::string::npos)
        << message;
  }
}

// Writes that convert (variable-length strings from char*, doubles stored as floats) go through
// a conversion buffer sized to the rows written: one row, a few, and more than its 1 MiB cap
// (converted in pieces) must all store what was given.
TEST(ExtendibleDataset, ConvertingWritesOfAnySizeStoreTheirValues) {
  test::TempDir dir;
  const auto path = dir.path() / "t.h5";
  const std::vector<std::size_t> batches = {1, 3, 200'000};  // the last: 1.6 MB of char*
  std::vector<std::string> words;
  std::vector<double> numbers;
  {
    H5Id file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    const h5::Handle text = h5::utf8_string_type({path.string(), "/kind"});
    ExtendibleSpec kind;
    kind.name = "kind";
    kind.file_type = text.get();
    ExtendibleSpec value;
    value.name = "value";
    value.file_type = H5T_IEEE_F32LE;
    ExtendibleDataset kinds(file, "/", kind, path.string()), values(file, "/", value, path.string());
    for (const std::size_t n : batches) {
      std::vector<const char*> pointers;
      const std::size_t first = words.size();
      for (std::size_t i = 0; i < n; ++i) {
        words.push_back(i % 2 ? "split" : "time_coarsen");
        numbers.push_back(0.25 * static_cast<double>(first + i));
      }
      for (std::size_t i = first; i < words.size(); ++i) pointers.push_back(words[i].c_str());
      kinds.append(pointers.data(), text.get(), n);
      values.append(std::span<const double>(numbers).subspan(first));
    }
    kinds.close();
    values.close();
  }
  H5Id file(test::open_read_only(path), H5Fclose);
  EXPECT_EQ(test::read_strings(file, "/kind"), words);
  const auto back = test::read_array<double>(file, "/value");
  ASSERT_EQ(back.values.size(), numbers.size());
  for (std::size_t i = 0; i < numbers.size(); i += 997) EXPECT_EQ(back.values[i], numbers[i]);
  EXPECT_EQ(back.values.back(), numbers.back());
}

TEST(ExtendibleDataset, ChunkRowsAimAtAboutFourKibibytes) {
  EXPECT_EQ(h5::chunk_rows_for(8, 1024), 512u);
  EXPECT_EQ(h5::chunk_rows_for(8, 128), 128u);          // scalars: capped
  EXPECT_EQ(h5::chunk_rows_for(56, 128), 73u);          // the seven time parts
  EXPECT_EQ(h5::chunk_rows_for(1000, 16), 4u);
  EXPECT_EQ(h5::chunk_rows_for(8192, 16), 1u);
  EXPECT_EQ(h5::chunk_rows_for(1'000'000, 16), 1u);     // huge rows: one per chunk
  EXPECT_EQ(h5::chunk_rows_for(0, 16), 16u);
}

}  // namespace
}  // namespace mrsim
