#pragma once
// A file kept byte for byte inside an HDF5 file, as a 1-D dataset of unsigned bytes. The
// checkpoint carries the run's log.h5 this way: HDF5 files are not crash-consistent, so a run
// killed while it flushes its log can leave a log.h5 that no longer reopens, and the copy taken
// with the checkpoint is what a resumed run goes on from (docs/output.md "Checkpoints").
#include <hdf5.h>

#include <filesystem>
#include <string>

#include "io/hdf5_error.hpp"

namespace mrsim::h5 {

/// Stores the bytes of `file` as dataset `name` under `parent`, copied in blocks (a large log
/// never sits in memory whole). Throws RunError naming the file or the dataset.
void embed_file(hid_t parent, const std::string& name, const std::filesystem::path& file,
                Where where);

/// Writes dataset `name` under `parent` back out as `file`, atomically: to `file`.tmp, synced,
/// then renamed over `file`. Throws RunError; `file` is untouched then.
void extract_file(hid_t parent, const std::string& name, const std::filesystem::path& file,
                  Where where);

}  // namespace mrsim::h5
