#include "io/extendible_dataset.hpp"

#include <algorithm>

#include "io/hdf5_attributes.hpp"
#include "io/hdf5_group.hpp"

namespace mrsim::h5 {
namespace {

// A chunk's dimensions: {rows, the row's dimensions...}.
std::vector<hsize_t> chunk_shape(const ExtendibleSpec& spec) {
  std::vector<hsize_t> chunk{std::max<hsize_t>(spec.chunk_rows, 1)};
  // A zero-sized trailing dimension (a level without points) still needs a chunk of >= 1.
  for (const hsize_t n : spec.row_shape) chunk.push_back(std::max<hsize_t>(n, 1));
  return chunk;
}

// Creation properties: chunked (required for an unlimited dimension), optionally deflated.
Handle creation_properties(const ExtendibleSpec& spec, Where where) {
  Handle properties = checked(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, where,
                              "create dataset properties");
  no_time_stamps(properties.get(), where);
  const std::vector<hsize_t> chunk = chunk_shape(spec);
  check(H5Pset_chunk(properties.get(), static_cast<int>(chunk.size()), chunk.data()), where,
        "set chunk size");
  if (spec.deflate_level > 0) {
    check(H5Pset_deflate(properties.get(), static_cast<unsigned>(spec.deflate_level)), where,
          "enable deflate compression");
  }
  return properties;
}

Handle empty_space(const ExtendibleSpec& spec, Where where) {
  std::vector<hsize_t> dims{0};
  std::vector<hsize_t> max_dims{H5S_UNLIMITED};
  for (const hsize_t n : spec.row_shape) {
    dims.push_back(n);
    // Chunks may not exceed a fixed dimension, so an empty one is made unlimited instead.
    max_dims.push_back(n == 0 ? H5S_UNLIMITED : n);
  }
  return checked(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max_dims.data()),
                 H5Sclose, where, "create dataspace");
}

}  // namespace

hsize_t chunk_rows_for(hsize_t row_bytes, hsize_t max_rows) {
  constexpr hsize_t kTargetChunkBytes = 4 * 1024;
  const hsize_t rows = kTargetChunkBytes / std::max<hsize_t>(row_bytes, 1);
  return std::clamp<hsize_t>(rows, 1, std::max<hsize_t>(max_rows, 1));
}

ExtendibleDataset::ExtendibleDataset(hid_t parent, const std::string& parent_path,
                                     const ExtendibleSpec& spec, const std::string& file,
                                     Mode mode)
    : row_shape_(spec.row_shape),
      path_(parent_path == "/" ? "/" + spec.name : parent_path + "/" + spec.name),
      file_(file) {
  if (mode == Mode::Reopen) {
    open_existing(parent, spec);
    return;
  }
  Handle space = empty_space(spec, where());
  Handle properties = creation_properties(spec, where());
  dataset_ = checked(H5Dcreate2(parent, spec.name.c_str(), spec.file_type, space.get(),
                                H5P_DEFAULT, properties.get(), H5P_DEFAULT),
                     H5Dclose, where(), "create dataset");
  file_type_ = checked(H5Dget_type(dataset_.get()), H5Tclose, where(), "get datatype");
  if (!spec.units.empty()) set_string_attribute(dataset_.get(), "units", spec.units, where());
  if (!spec.description.empty()) {
    set_string_attribute(dataset_.get(), "description", spec.description, where());
  }
  // A dimension of zero (a level without points) has chunks of one: no whole rows to write.
  if (std::find(spec.row_shape.begin(), spec.row_shape.end(), 0) == spec.row_shape.end())
    tail_ = TailChunk::of(file_type_.get(), chunk_shape(spec), spec.deflate_level,
                          spec.deflate_runs, where());
}

void ExtendibleDataset::open_existing(hid_t parent, const ExtendibleSpec& spec) {
  dataset_ = checked(H5Dopen2(parent, spec.name.c_str(), H5P_DEFAULT), H5Dclose, where(),
                     "open dataset");
  file_type_ = checked(H5Dget_type(dataset_.get()), H5Tclose, where(), "get datatype");
  Handle space = checked(H5Dget_space(dataset_.get()), H5Sclose, where(), "get dataspace");
  std::vector<hsize_t> dims(spec.row_shape.size() + 1);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  bool fits = rank == static_cast<int>(dims.size());
  if (fits) {
    check(H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr), where(), "read extent");
    fits = std::equal(spec.row_shape.begin(), spec.row_shape.end(), dims.begin() + 1);
  }
  if (!fits) throw_error(where(), "append to it: its rows are not those this run writes");
  rows_ = dims[0];
  tail_ = TailChunk::of(dataset_.get(), spec.deflate_runs, where());
}

void ExtendibleDataset::truncate(hsize_t rows) {
  if (rows > rows_)
    throw_error(where(), "keep " + std::to_string(rows) + " rows: it holds " +
                             std::to_string(rows_));
  std::vector<hsize_t> extent{rows};
  extent.insert(extent.end(), row_shape_.begin(), row_shape_.end());
  if (tail_) tail_->forget();  // HDF5 clears the cut rows of the last chunk kept
  check(H5Dset_extent(dataset_.get(), extent.data()), where(), "truncate dataset");
  rows_ = rows;
}

hsize_t ExtendibleDataset::row_size() const {
  hsize_t size = 1;
  for (const hsize_t n : row_shape_) size *= n;
  return size;
}

void ExtendibleDataset::append(const void* data, hid_t memory_type, hsize_t rows) {
  if (rows == 0) return;
  std::vector<hsize_t> extent{rows_ + rows};
  extent.insert(extent.end(), row_shape_.begin(), row_shape_.end());
  check(H5Dset_extent(dataset_.get(), extent.data()), where(), "extend dataset");
  const hsize_t old_rows = rows_;
  rows_ += rows;  // the extent is already grown; keep the count in step even if writing fails
  if (row_size() == 0) return;  // nothing to write in rows of zero values
  // Values whose bytes in memory are those of the file go straight into their chunk.
  if (tail_ && H5Tequal(memory_type, file_type_.get()) > 0) {
    tail_->write(dataset_.get(), static_cast<const unsigned char*>(data), old_rows, rows, where());
    return;
  }
  if (tail_) tail_->forget();
  write_converted(data, memory_type, old_rows, rows);
}

void ExtendibleDataset::write_converted(const void* data, hid_t memory_type, hsize_t first,
                                        hsize_t rows) {
  std::vector<hsize_t> start(row_shape_.size() + 1, 0);
  start[0] = first;
  std::vector<hsize_t> count{rows};
  count.insert(count.end(), row_shape_.begin(), row_shape_.end());
  Handle file_space = checked(H5Dget_space(dataset_.get()), H5Sclose, where(), "get dataspace");
  check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(),
                            nullptr),
        where(), "select new rows");
  Handle memory_space = checked(H5Screate_simple(static_cast<int>(count.size()), count.data(),
                                                 nullptr),
                                H5Sclose, where(), "create memory dataspace");
  check(H5Dwrite(dataset_.get(), memory_type, memory_space.get(), file_space.get(),
                 transfer_properties(memory_type, rows), data),
        where(), "write rows");
}

// A write that converts (the events' kinds: char* in memory, variable-length strings in the
// file; H5Tequal() cannot tell, since variable-length data always converts) goes through HDF5's
// type-conversion and background buffers, 1 MiB each by default and allocated zeroed at every
// write: most of log.h5's cost per frame on liver_probe. They are sized to the rows written
// instead (HDF5 converts in pieces of the buffer's size, so any size of one element or more
// writes the same values). A write that does not convert allocates no buffer either way.
hid_t ExtendibleDataset::transfer_properties(hid_t memory_type, hsize_t rows) {
  constexpr hsize_t kLeast = 1024, kMost = hsize_t{1} << 20;  // bytes; HDF5's default is kMost
  const hsize_t element = std::max(H5Tget_size(memory_type), H5Tget_size(file_type_.get()));
  const hsize_t bytes = std::clamp<hsize_t>(rows * std::max<hsize_t>(row_size(), 1) * element,
                                            std::max(kLeast, element), kMost);
  if (!transfer_.valid())
    transfer_ = checked(H5Pcreate(H5P_DATASET_XFER), H5Pclose, where(),
                        "create transfer properties");
  check(H5Pset_buffer(transfer_.get(), bytes, nullptr, nullptr), where(),
        "set conversion buffer size");
  return transfer_.get();
}

void ExtendibleDataset::close() { check(dataset_.close(), where(), "close dataset"); }

}  // namespace mrsim::h5
