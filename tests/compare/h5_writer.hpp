#pragma once
// Small HDF5 files written with the plain C API, for the tests of the log comparison.
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace mrsim::test {

class H5Writer {
 public:
  explicit H5Writer(const std::filesystem::path& file)
      : file_(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)) {
    if (file_ < 0) throw std::runtime_error("cannot create " + file.string());
  }
  ~H5Writer() { H5Fclose(file_); }
  H5Writer(const H5Writer&) = delete;
  H5Writer& operator=(const H5Writer&) = delete;

  void doubles(const std::string& path, const std::vector<hsize_t>& dims,
               const std::vector<double>& values) {
    write(path, dims, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data());
  }
  void int64s(const std::string& path, const std::vector<hsize_t>& dims,
              const std::vector<std::int64_t>& values) {
    write(path, dims, H5T_STD_I64LE, H5T_NATIVE_INT64, values.data());
  }
  void int8s(const std::string& path, const std::vector<hsize_t>& dims,
             const std::vector<std::int8_t>& values) {
    write(path, dims, H5T_STD_I8LE, H5T_NATIVE_INT8, values.data());
  }
  void strings(const std::string& path, const std::vector<std::string>& values) {
    std::vector<const char*> raw;
    for (const std::string& v : values) raw.push_back(v.c_str());
    const hid_t type = string_type();
    write(path, {values.size()}, type, type, raw.data());
    H5Tclose(type);
  }
  void string_attribute(const std::string& object, const std::string& name,
                        const std::string& value) {
    const hid_t type = string_type();
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute = H5Acreate_by_name(file_, object.c_str(), name.c_str(), type, space,
                                              H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const char* raw = value.c_str();
    if (attribute < 0 || H5Awrite(attribute, type, &raw) < 0)
      throw std::runtime_error("cannot write " + name);
    H5Aclose(attribute);
    H5Sclose(space);
    H5Tclose(type);
  }
  void int_attribute(const std::string& object, const std::string& name, std::int64_t value) {
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute = H5Acreate_by_name(file_, object.c_str(), name.c_str(), H5T_STD_I64LE,
                                              space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (attribute < 0 || H5Awrite(attribute, H5T_NATIVE_INT64, &value) < 0)
      throw std::runtime_error("cannot write " + name);
    H5Aclose(attribute);
    H5Sclose(space);
  }

 private:
  static hid_t string_type() {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    return type;
  }
  void write(const std::string& path, const std::vector<hsize_t>& dims, hid_t file_type,
             hid_t memory_type, const void* data) {
    const hid_t links = H5Pcreate(H5P_LINK_CREATE);
    H5Pset_create_intermediate_group(links, 1);
    const hid_t space = dims.empty()
                            ? H5Screate(H5S_SCALAR)
                            : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
    const hid_t dataset =
        H5Dcreate2(file_, path.c_str(), file_type, space, links, H5P_DEFAULT, H5P_DEFAULT);
    if (dataset < 0 || H5Dwrite(dataset, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) {
      throw std::runtime_error("cannot write " + path);
    }
    H5Dclose(dataset);
    H5Sclose(space);
    H5Pclose(links);
  }

  hid_t file_;
};

}  // namespace mrsim::test
