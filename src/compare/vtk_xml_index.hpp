#pragma once
// The two index files of a VTK time series, read as XML: frames.pvd (a "Collection" of one
// DataSet per frame) and frames/frame_NNNNNN.vtm (a "vtkMultiBlockDataSet" of one DataSet per
// block). Both are small; the heavy pieces they point to are read by VTK's own readers.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace mrsim {

using XmlAttributes = std::map<std::string, std::string>;

/// The attributes of every DataSet element of the `type` section ("Collection",
/// "vtkMultiBlockDataSet"), in document order. Throws InputError naming `file` when it is
/// missing, not well-formed XML, not a VTKFile of that type, or nests blocks (mrsim writes
/// flat multiblocks only).
std::vector<XmlAttributes> read_dataset_entries(const std::filesystem::path& file,
                                                const std::string& type);

/// The value of `name`, or InputError naming `file` and the entry when it is absent.
const std::string& required_attribute(const XmlAttributes& entry, const std::string& name,
                                      const std::filesystem::path& file);

}  // namespace mrsim
