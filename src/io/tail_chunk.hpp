#pragma once
// The last chunk of an appendable dataset (io/extendible_dataset.hpp), kept in memory and
// written whole to its place in the file by H5Dwrite_chunk() at each append. Through H5Dwrite()
// a frame's few rows went through HDF5's chunk cache, its dataspace selections and, for a
// deflated status row, its filter pipeline (zlib set up anew per chunk), and the frame's flush
// then wrote every dirty chunk again: 8 % of liver_probe's adaptive run (issue 17). The chunk
// in the file is the same: the rows appended, zeros after them (the datasets' fill value), a
// deflated chunk as HDF5's deflate filter stores it.
#include <hdf5.h>

#include <memory>
#include <optional>
#include <vector>

#include "io/hdf5_error.hpp"
#include "io/hdf5_handle.hpp"
#include "io/zlib_deflater.hpp"

namespace mrsim::h5 {

class TailChunk {
 public:
  /// For `dataset`, or nothing when its chunks are not written here: a filter other than
  /// deflate, a fill value of its own, values other than fixed-size numbers, chunks that do not
  /// hold whole rows.
  /// `runs`: deflated with zlib's run-length strategy (any zlib stream is one HDF5 inflates).
  static std::optional<TailChunk> of(hid_t dataset, bool runs, Where where);
  /// For a dataset just created with these chunks (`shape`: {rows, the row's dimensions...}),
  /// values of `file_type` and this deflate level (0: none), without asking HDF5.
  static std::optional<TailChunk> of(hid_t file_type, std::vector<hsize_t> shape,
                                     int deflate_level, bool runs, Where where);

  /// Writes the dataset's rows [first, first + count) from `data` (their bytes as in the file;
  /// the extent already holds them). The rows before `first` in its chunk are this object's, or
  /// read back from the file after forget().
  void write(hid_t dataset, const unsigned char* data, hsize_t first, hsize_t count, Where where);
  /// The file's rows changed without this object (cut back, or written through H5Dwrite()).
  void forget() { chunk_ = kNone; }

 private:
  static constexpr hsize_t kNone = ~hsize_t{0};
  TailChunk() = default;
  void load(hid_t dataset, hsize_t chunk, hsize_t first_new_row, Where where);
  void store(hid_t dataset, Where where);

  Handle type_;                 // the values' type in the file, to read rows back as they are
  std::vector<hsize_t> shape_;  // a chunk's dimensions: {rows, the row's dimensions...}
  hsize_t row_bytes_ = 0;
  std::vector<unsigned char> bytes_;  // the chunk `chunk_`, uncompressed
  hsize_t chunk_ = kNone;
  std::vector<hsize_t> offset_;  // of the chunk in the dataset, for H5Dwrite_chunk()
  std::unique_ptr<ZlibDeflater> deflater_;  // deflated datasets only
};

}  // namespace mrsim::h5
