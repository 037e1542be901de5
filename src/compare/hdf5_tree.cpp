#include "compare/hdf5_tree.hpp"

#include <hdf5.h>

#include <cstring>
#include <utility>

#include "core/error.hpp"
#include "io/hdf5_error.hpp"
#include "io/hdf5_handle.hpp"

namespace mrsim {
namespace {

using h5::Handle;
using h5::Where;

// mrsim_io's HDF5 helpers throw RunError (a failed write during a run). For compare, a file
// it cannot read is bad input: exit code 2.
template <class F>
auto as_input_error(F&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const RunError& e) {
    throw InputError(e.what());
  }
}

// The visitors run inside HDF5's C code: nothing may throw through it.
herr_t collect_link(hid_t, const char* name, const H5L_info_t* info, void* names) {
  try {
    if (info->type == H5L_TYPE_HARD)
      static_cast<std::vector<std::string>*>(names)->emplace_back(name);
    return 0;
  } catch (...) {
    return -1;
  }
}

herr_t collect_attribute(hid_t, const char* name, const H5A_info_t*, void* names) {
  try {
    static_cast<std::vector<std::string>*>(names)->emplace_back(name);
    return 0;
  } catch (...) {
    return -1;
  }
}

std::vector<std::string> attribute_names(hid_t object, Where where) {
  std::vector<std::string> names;
  hsize_t position = 0;
  h5::check(H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, &position, collect_attribute, &names),
            where, "list the attributes");
  return names;
}

void add_attributes(std::vector<Hdf5Item>& items, hid_t object, const std::string& path,
                    const std::string& file) {
  const std::string prefix = path == "/" ? "/" : path;
  for (std::string& name : attribute_names(object, {file, path})) {
    items.push_back({prefix + "@" + name, path, std::move(name)});
  }
}

std::vector<Hdf5Item> list_items(hid_t file_id, const std::string& file) {
  std::vector<Hdf5Item> items;
  add_attributes(items, file_id, "/", file);
  std::vector<std::string> links;
  h5::check(H5Lvisit(file_id, H5_INDEX_NAME, H5_ITER_INC, collect_link, &links), {file, "/"},
            "list the objects");
  for (const std::string& link : links) {
    const std::string path = "/" + link;
    const Handle object = h5::checked(H5Oopen(file_id, path.c_str(), H5P_DEFAULT), H5Oclose,
                                      {file, path}, "open the object");
    if (H5Iget_type(object.get()) == H5I_DATASET) items.push_back({path, path, ""});
    add_attributes(items, object.get(), path, file);
  }
  return items;
}

// A dataset or an attribute, opened with its type and dataspace.
struct Source {
  Handle object;
  Handle type;
  Handle space;
  bool attribute = false;
  Where where;

  void read(hid_t memory_type, void* buffer) const {
    const herr_t status =
        attribute ? H5Aread(object.get(), memory_type, buffer)
                  : H5Dread(object.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer);
    h5::check(status, where, "read the values");
  }
};

Source open_source(hid_t file_id, const Hdf5Item& item, Where where) {
  Source s;
  s.where = where;
  s.attribute = !item.attribute.empty();
  if (s.attribute) {
    s.object = h5::checked(H5Aopen_by_name(file_id, item.object.c_str(), item.attribute.c_str(),
                                           H5P_DEFAULT, H5P_DEFAULT),
                           H5Aclose, where, "open the attribute");
    s.type = h5::checked(H5Aget_type(s.object.get()), H5Tclose, where, "get the type");
    s.space = h5::checked(H5Aget_space(s.object.get()), H5Sclose, where, "get the dataspace");
  } else {
    s.object = h5::checked(H5Dopen2(file_id, item.object.c_str(), H5P_DEFAULT), H5Dclose, where,
                           "open the dataset");
    s.type = h5::checked(H5Dget_type(s.object.get()), H5Tclose, where, "get the type");
    s.space = h5::checked(H5Dget_space(s.object.get()), H5Sclose, where, "get the dataspace");
  }
  return s;
}

Shape shape_of(const Source& s) {
  const H5S_class_t kind = H5Sget_simple_extent_type(s.space.get());
  if (kind == H5S_SCALAR) return {};
  if (kind == H5S_NULL) return {0};
  const int rank = H5Sget_simple_extent_ndims(s.space.get());
  if (rank < 0) h5::throw_error(s.where, "get the rank");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  h5::check(H5Sget_simple_extent_dims(s.space.get(), dims.data(), nullptr), s.where,
            "get the shape");
  return Shape(dims.begin(), dims.end());
}

// Frees what HDF5 allocated for variable-length strings, whatever happens while copying them.
struct VlenStrings {
  std::vector<char*> pointers;
  hid_t type;
  hid_t space;
  ~VlenStrings() {
    if (!pointers.empty()) (void)H5Dvlen_reclaim(type, space, H5P_DEFAULT, pointers.data());
  }
};

std::vector<std::string> read_variable_strings(const Source& s, std::size_t count) {
  const Handle memory = h5::checked(H5Tcopy(H5T_C_S1), H5Tclose, s.where, "create a string type");
  h5::check(H5Tset_size(memory.get(), H5T_VARIABLE), s.where, "make the string type variable");
  h5::check(H5Tset_cset(memory.get(), H5Tget_cset(s.type.get())), s.where, "set the character set");
  VlenStrings raw{std::vector<char*>(count, nullptr), memory.get(), s.space.get()};
  s.read(memory.get(), raw.pointers.data());
  std::vector<std::string> texts;
  texts.reserve(count);
  for (const char* text : raw.pointers) texts.emplace_back(text != nullptr ? text : "");
  return texts;
}

// Fixed-size elements (fixed-length strings, compounds, enums): `count` raw chunks of the
// memory type's size; strings end at their first NUL.
std::vector<std::string> read_fixed_elements(const Source& s, hid_t memory, std::size_t count,
                                             bool text) {
  const std::size_t size = H5Tget_size(memory);
  if (size == 0) h5::throw_error(s.where, "get the element size");
  std::vector<char> buffer(count * size);
  if (count > 0) s.read(memory, buffer.data());
  std::vector<std::string> elements;
  elements.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const char* begin = buffer.data() + i * size;
    elements.emplace_back(begin, text ? ::strnlen(begin, size) : size);
  }
  return elements;
}

std::vector<std::string> read_bytes(const Source& s, std::size_t count) {
  const hid_t type = s.type.get();
  // Pointers inside the elements would make raw bytes meaningless.
  if (H5Tdetect_class(type, H5T_VLEN) > 0 || H5Tdetect_class(type, H5T_STRING) > 0 ||
      H5Tdetect_class(type, H5T_REFERENCE) > 0) {
    throw InputError(
        std::string(s.where.file) + ":" + std::string(s.where.object) +
        ": unsupported HDF5 type (variable-length data or references inside a compound)");
  }
  const Handle memory = h5::checked(H5Tget_native_type(type, H5T_DIR_ASCEND), H5Tclose, s.where,
                                    "get the native type");
  return read_fixed_elements(s, memory.get(), count, false);
}

ValueArray read_values(const Source& s) {
  ValueArray v;
  v.shape = shape_of(s);
  const std::size_t count = element_count(v.shape);
  switch (H5Tget_class(s.type.get())) {
    case H5T_FLOAT:
      v.kind = ValueKind::Real;
      v.reals.resize(count);
      if (count > 0) s.read(H5T_NATIVE_DOUBLE, v.reals.data());
      break;
    case H5T_INTEGER:
      v.kind = ValueKind::Integer;
      v.integers.resize(count);
      if (count > 0) s.read(H5T_NATIVE_INT64, v.integers.data());
      break;
    case H5T_STRING:
      v.kind = ValueKind::Text;
      v.texts = H5Tis_variable_str(s.type.get()) > 0
                    ? read_variable_strings(s, count)
                    : read_fixed_elements(s, s.type.get(), count, true);
      break;
    default:
      v.kind = ValueKind::Bytes;
      v.texts = read_bytes(s, count);
      break;
  }
  return v;
}

}  // namespace

struct Hdf5Tree::Impl {
  std::string file;
  Handle id;
  std::vector<Hdf5Item> items;
};

Hdf5Tree::Hdf5Tree(const std::filesystem::path& file) : impl_(std::make_unique<Impl>()) {
  impl_->file = file.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw InputError(impl_->file + ": file not found");
  h5::silence_automatic_error_printing();
  as_input_error([&] {
    const Where where{impl_->file, ""};
    const Handle access =
        h5::checked(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, where, "create a property list");
    h5::check(H5Pset_file_locking(access.get(), false, true), where, "disable file locking");
    impl_->id = h5::checked(H5Fopen(impl_->file.c_str(), H5F_ACC_RDONLY, access.get()), H5Fclose,
                            where, "open the file as HDF5");
    impl_->items = list_items(impl_->id.get(), impl_->file);
  });
}

Hdf5Tree::~Hdf5Tree() = default;

const std::vector<Hdf5Item>& Hdf5Tree::items() const { return impl_->items; }

ValueArray Hdf5Tree::read(const Hdf5Item& item) const {
  return as_input_error([&] {
    const Where where{impl_->file, item.name};
    return read_values(open_source(impl_->id.get(), item, where));
  });
}

}  // namespace mrsim
