#pragma once
// Every dataset and every attribute of an HDF5 file (log.h5), listed once by name and read one
// at a time, so that comparing two logs holds one pair of datasets in memory, never the files.
// hdf5.h stays out of this header (HDF5 is a private dependency of mrsim_compare).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "compare/value_array.hpp"

namespace mrsim {

struct Hdf5Item {
  // "/frames/time" for a dataset; "/frames/time@units" for an attribute, "/@scenario" for one
  // of the root group.
  std::string name;
  std::string object;     // path of the dataset, or of the object holding the attribute
  std::string attribute;  // empty for a dataset
};

class Hdf5Tree {
 public:
  /// Opens `file` read-only (without file locking: a comparison only reads). Throws
  /// InputError naming the file when it is missing or not a readable HDF5 file.
  explicit Hdf5Tree(const std::filesystem::path& file);
  ~Hdf5Tree();
  Hdf5Tree(const Hdf5Tree&) = delete;
  Hdf5Tree& operator=(const Hdf5Tree&) = delete;

  /// Root attributes, then every dataset (groups recursively, by name) followed by its
  /// attributes, and every group's attributes.
  const std::vector<Hdf5Item>& items() const;
  /// The values of one item. Throws InputError naming the file and the item if they cannot be
  /// read (corrupt file, unsupported type such as variable-length non-strings).
  ValueArray read(const Hdf5Item& item) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mrsim
