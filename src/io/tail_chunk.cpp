#include "io/tail_chunk.hpp"

#include <algorithm>
#include <cstring>
#include <functional>
#include <numeric>

namespace mrsim::h5 {
namespace {

// The deflate level of `dcpl`'s filters: 0 without any, nothing with another filter.
std::optional<int> deflate_level(hid_t dcpl) {
  const int filters = H5Pget_nfilters(dcpl);
  if (filters < 0 || filters > 1) return std::nullopt;
  if (filters == 0) return 0;
  unsigned flags = 0, config = 0, values[1] = {0};
  std::size_t count = 1;
  const H5Z_filter_t id = H5Pget_filter2(dcpl, 0, &flags, &count, values, 0, nullptr, &config);
  if (id != H5Z_FILTER_DEFLATE || count < 1) return std::nullopt;
  return static_cast<int>(values[0]);
}

bool fixed_size_numbers(hid_t type) {
  const H5T_class_t kind = H5Tget_class(type);
  return kind == H5T_INTEGER || kind == H5T_FLOAT;
}

}  // namespace

std::optional<TailChunk> TailChunk::of(hid_t dataset, bool runs, Where where) {
  Handle dcpl = checked(H5Dget_create_plist(dataset), H5Pclose, where, "get creation properties");
  Handle space = checked(H5Dget_space(dataset), H5Sclose, where, "get dataspace");
  Handle type = checked(H5Dget_type(dataset), H5Tclose, where, "get datatype");
  H5D_fill_value_t fill = H5D_FILL_VALUE_ERROR;
  if (H5Pget_layout(dcpl.get()) != H5D_CHUNKED || H5Pfill_value_defined(dcpl.get(), &fill) < 0 ||
      fill != H5D_FILL_VALUE_DEFAULT)
    return std::nullopt;
  const std::optional<int> level = deflate_level(dcpl.get());
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (!level || rank < 1) return std::nullopt;
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank)), shape(dims.size());
  if (H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0 ||
      H5Pget_chunk(dcpl.get(), rank, shape.data()) != rank)
    return std::nullopt;
  // Whole rows per chunk: each row dimension's chunk is the dimension itself.
  if (!std::equal(dims.begin() + 1, dims.end(), shape.begin() + 1)) return std::nullopt;
  return of(type.get(), std::move(shape), *level, runs, where);
}

std::optional<TailChunk> TailChunk::of(hid_t file_type, std::vector<hsize_t> shape,
                                       int deflate_level, bool runs, Where where) {
  if (!fixed_size_numbers(file_type) || shape.empty() || shape[0] == 0) return std::nullopt;
  TailChunk tail;
  tail.row_bytes_ = std::accumulate(shape.begin() + 1, shape.end(), hsize_t{1},
                                    std::multiplies<>()) * H5Tget_size(file_type);
  if (tail.row_bytes_ == 0) return std::nullopt;
  tail.type_ = checked(H5Tcopy(file_type), H5Tclose, where, "copy datatype");
  tail.shape_ = std::move(shape);
  tail.offset_.assign(tail.shape_.size(), 0);
  if (deflate_level > 0)
    tail.deflater_ =
        std::make_unique<ZlibDeflater>(deflate_level, runs ? Z_RLE : Z_DEFAULT_STRATEGY);
  return tail;
}

void TailChunk::write(hid_t dataset, const unsigned char* data, hsize_t first, hsize_t count,
                      Where where) {
  const hsize_t rows = shape_[0];
  for (hsize_t row = first; row < first + count;) {
    const hsize_t chunk = row / rows;
    const hsize_t end = std::min(first + count, (chunk + 1) * rows);
    if (chunk != chunk_) load(dataset, chunk, row, where);
    std::memcpy(bytes_.data() + (row - chunk * rows) * row_bytes_,
                data + (row - first) * row_bytes_, (end - row) * row_bytes_);
    store(dataset, where);
    row = end;
  }
}

void TailChunk::load(hid_t dataset, hsize_t chunk, hsize_t first_new_row, Where where) {
  chunk_ = kNone;  // until loaded whole
  bytes_.assign(shape_[0] * row_bytes_, 0);
  const hsize_t start = chunk * shape_[0];
  if (first_new_row > start) {  // rows of this chunk already in the file
    std::vector<hsize_t> origin(shape_.size(), 0), count = shape_;
    origin[0] = start;
    count[0] = first_new_row - start;
    Handle file_space = checked(H5Dget_space(dataset), H5Sclose, where, "get dataspace");
    check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, origin.data(), nullptr,
                              count.data(), nullptr),
          where, "select the last chunk's rows");
    Handle memory = checked(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr),
                            H5Sclose, where, "create memory dataspace");
    check(H5Dread(dataset, type_.get(), memory.get(), file_space.get(), H5P_DEFAULT, bytes_.data()),
          where, "read the last chunk's rows back");
  }
  chunk_ = chunk;
  offset_[0] = start;
}

void TailChunk::store(hid_t dataset, Where where) {
  std::span<const unsigned char> out(bytes_);
  if (deflater_) out = deflater_->compress(out);
  check(H5Dwrite_chunk(dataset, H5P_DEFAULT, 0, offset_.data(), out.size(), out.data()), where,
        "write chunk");
}

}  // namespace mrsim::h5
