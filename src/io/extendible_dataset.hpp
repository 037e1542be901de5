#pragma once
// A dataset that grows by whole rows along its first (unlimited) dimension: the building block
// of every per-frame or per-event record in log.h5 (and of /tool/* later). Chunked, optionally
// deflate-compressed; each append extends the extent and writes the new rows: numbers straight
// into their chunk (io/tail_chunk.hpp), values HDF5 converts (variable-length strings) through
// H5Dwrite().
#include <hdf5.h>

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/hdf5_handle.hpp"
#include "io/hdf5_types.hpp"
#include "io/tail_chunk.hpp"

namespace mrsim::h5 {

struct ExtendibleSpec {
  std::string name;               // relative to the parent group
  hid_t file_type = -1;           // not owned; must outlive the constructor call
  std::vector<hsize_t> row_shape; // dimensions after the first; empty: one value per row
  hsize_t chunk_rows = 1024;      // rows per chunk
  int deflate_level = 0;          // 0: uncompressed, 1..9: zlib level
  // Rows of a few values in long runs (a level's statuses): deflated with zlib's run-length
  // strategy (Z_RLE), for which they came out smaller than at the default, in half the time.
  bool deflate_runs = false;
  std::string units;              // stored as attribute `units` ("" = none)
  std::string description;        // stored as attribute `description` ("" = none)
};

class ExtendibleDataset {
 public:
  ExtendibleDataset() = default;
  /// Create: makes `spec.name` under `parent` with zero rows (RunError if it exists). Reopen:
  /// opens it with its rows (a log reopened to resume a run; its row shape must be the spec's).
  /// `file` and `parent_path` only name things in error messages.
  enum class Mode { Create, Reopen };
  ExtendibleDataset(hid_t parent, const std::string& parent_path, const ExtendibleSpec& spec,
                    const std::string& file, Mode mode = Mode::Create);

  /// Appends `rows` rows read from `data` (row-major, `memory_type` elements).
  void append(const void* data, hid_t memory_type, hsize_t rows);

  /// Appends whole rows; `values.size()` must be a multiple of the row size.
  template <class T>
  void append(std::span<const T> values) {
    const hsize_t per_row = row_size();
    if (per_row == 0 ? !values.empty() : values.size() % per_row != 0) {
      throw std::invalid_argument(path_ + ": " + std::to_string(values.size()) +
                                  " values do not make whole rows of " + std::to_string(per_row));
    }
    append(values.data(), TypeOf<T>::memory(), per_row == 0 ? 1 : values.size() / per_row);
  }

  hsize_t rows() const { return rows_; }
  /// Keeps the first `rows` rows (a resumed run drops what a killed run wrote after its
  /// checkpoint). Throws RunError when there are fewer.
  void truncate(hsize_t rows);
  hsize_t row_size() const;
  hid_t id() const { return dataset_.get(); }
  const std::string& path() const { return path_; }
  /// Closes the dataset, reporting a failure (the destructor closes silently).
  void close();

 private:
  Where where() const { return {file_, path_}; }
  void open_existing(hid_t parent, const ExtendibleSpec& spec);
  hid_t transfer_properties(hid_t memory_type, hsize_t rows);
  void write_converted(const void* data, hid_t memory_type, hsize_t first, hsize_t rows);
  Handle dataset_;
  Handle file_type_;  // the dataset's element type in the file
  Handle transfer_;   // transfer properties: the conversion buffer sized to each write
  std::optional<TailChunk> tail_;  // nothing: every write goes through H5Dwrite()
  std::vector<hsize_t> row_shape_;
  hsize_t rows_ = 0;
  std::string path_;  // full path in the file, for messages
  std::string file_;
};

/// Chunk rows for rows of `row_bytes` bytes: about 4 KiB per chunk (at least 1 row, at most
/// `max_rows`). Every frame's flush rewrites each growing dataset's last chunk whole, so the
/// chunk is what a frame costs in writes (liver_probe: 45 MB written for its log with 64 KiB
/// chunks, 7 MB with 4 KiB).
hsize_t chunk_rows_for(hsize_t row_bytes, hsize_t max_rows);

}  // namespace mrsim::h5
