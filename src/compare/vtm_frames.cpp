#include "compare/vtm_frames.hpp"

#include <vtkAbstractArray.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLGenericDataObjectReader.h>
#include <vtkXMLMultiBlockDataReader.h>

#include <new>
#include <optional>
#include <type_traits>

#include "compare/vtk_xml_index.hpp"
#include "core/error.hpp"
#include "io/vtk_error_capture.hpp"
#include "mesh/mesh_input.hpp"
#include "mesh/vtu_header_check.hpp"

namespace mrsim {
namespace {

namespace fs = std::filesystem;

struct Piece {
  std::string name;
  fs::path file;
  std::optional<VtuDeclared> declared;  // .vtu: the counts its header announces
};

// "#3" for a block or array without a name. Appended: GCC 12 warns falsely on "#" + string
// (bug 105651).
std::string unnamed(std::size_t index) {
  std::string text = "#";
  text += std::to_string(index);
  return text;
}

InputError piece_error(const Piece& piece, const fs::path& vtm, const std::string& message) {
  return InputError(piece.file.string() + " (block " + piece.name + " of " + vtm.string() +
                    "): " + message);
}

std::vector<Piece> list_pieces(const fs::path& vtm) {
  std::vector<Piece> pieces;
  for (const XmlAttributes& entry : read_dataset_entries(vtm, "vtkMultiBlockDataSet")) {
    const auto name = entry.find("name");
    Piece piece{name != entry.end() ? name->second : unnamed(pieces.size()),
                vtm.parent_path() / required_attribute(entry, "file", vtm), std::nullopt};
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

// VTK trusts the sizes in a piece's header: a lying one makes it allocate gigabytes. The
// .vtu check of the mesh readers bounds them by the file's size first.
void check_piece(Piece& piece, const fs::path& vtm) {
  std::error_code ec;
  if (!fs::is_regular_file(piece.file, ec)) throw piece_error(piece, vtm, "file not found");
  if (piece.file.extension() == ".vtu")
    piece.declared = check_vtu_header(read_whole_file(piece.file), piece.file);
}

// VTK's messages on reading one piece alone; empty when it reads cleanly.
std::string piece_failure(const Piece& piece) {
  VtkErrorCapture capture;
  auto reader = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
  reader->SetFileName(piece.file.c_str());
  try {
    reader->Update();
  } catch (const std::bad_alloc&) {
    return "VTK ran out of memory: a size in the file is wrong";
  }
  if (capture.any()) return capture.summary();
  return reader->GetErrorCode() != 0 ? "error code " + std::to_string(reader->GetErrorCode())
                                     : std::string();
}

// The multiblock reader's messages do not say which piece failed: read them one by one to
// name it (on this error path only).
[[noreturn]] void throw_frame_error(const std::vector<Piece>& pieces, const fs::path& vtm,
                                    const std::string& what) {
  for (const Piece& piece : pieces) {
    const std::string failure = piece_failure(piece);
    if (!failure.empty())
      throw piece_error(piece, vtm,
                        "VTK could not read it (truncated or corrupt file): " + failure);
  }
  throw InputError(vtm.string() + ": VTK could not read the frame: " + what);
}

vtkSmartPointer<vtkMultiBlockDataSet> read_multiblock(const fs::path& vtm,
                                                      const std::vector<Piece>& pieces) {
  VtkErrorCapture capture;  // outlives the reader and the inner piece readers it creates
  auto reader = vtkSmartPointer<vtkXMLMultiBlockDataReader>::New();
  reader->SetFileName(vtm.c_str());
  try {
    reader->Update();
  } catch (const std::bad_alloc&) {
    // A size in a piece's binary headers can lie (the .vtp pieces are not checked first).
    throw_frame_error(pieces, vtm, "VTK ran out of memory: a size in a piece is wrong");
  }
  if (capture.any()) throw_frame_error(pieces, vtm, capture.summary());
  if (reader->GetErrorCode() != 0)
    throw_frame_error(pieces, vtm, "error code " + std::to_string(reader->GetErrorCode()));
  vtkSmartPointer<vtkMultiBlockDataSet> blocks =
      vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
  if (blocks == nullptr) throw InputError(vtm.string() + ": VTK returned no multiblock dataset");
  return blocks;
}

template <class T>
void copy_numbers(const T* data, std::size_t count, ValueArray& v) {
  if constexpr (std::is_floating_point_v<T>) {
    v.kind = ValueKind::Real;
    v.reals.assign(data, data + count);
  } else {
    v.kind = ValueKind::Integer;
    v.integers.resize(count);
    for (std::size_t i = 0; i < count; ++i) v.integers[i] = static_cast<std::int64_t>(data[i]);
  }
}

Shape tuple_shape(vtkAbstractArray* array) {
  const auto tuples = static_cast<std::size_t>(array->GetNumberOfTuples());
  const auto components = static_cast<std::size_t>(array->GetNumberOfComponents());
  return components == 1 ? Shape{tuples} : Shape{tuples, components};
}

ValueArray numeric_values(vtkDataArray* array, const std::string& where) {
  ValueArray v;
  v.shape = tuple_shape(array);
  const std::size_t count = element_count(v.shape);
  switch (array->GetDataType()) {
    vtkTemplateMacro(copy_numbers(static_cast<const VTK_TT*>(array->GetVoidPointer(0)), count, v));
    default:
      throw InputError(where + ": unsupported VTK array type " +
                       std::to_string(array->GetDataType()));
  }
  return v;
}

ValueArray string_values(vtkStringArray* array) {
  ValueArray v;
  v.kind = ValueKind::Text;
  v.shape = tuple_shape(array);
  const vtkIdType count = array->GetNumberOfValues();
  for (vtkIdType i = 0; i < count; ++i) v.texts.push_back(array->GetValue(i));
  return v;
}

ValueArray array_values(vtkAbstractArray* array, const std::string& where) {
  if (auto* numbers = vtkDataArray::SafeDownCast(array)) return numeric_values(numbers, where);
  if (auto* strings = vtkStringArray::SafeDownCast(array)) return string_values(strings);
  throw InputError(where + ": unsupported VTK array class " + array->GetClassName());
}

ValueArray point_values(vtkDataSet* data, const std::string& where) {
  auto* point_set = vtkPointSet::SafeDownCast(data);
  if (point_set != nullptr && point_set->GetPoints() != nullptr) {
    return numeric_values(point_set->GetPoints()->GetData(), where);
  }
  ValueArray v;  // other datasets (or none): coordinates one by one
  v.shape = {static_cast<std::size_t>(data->GetNumberOfPoints()), 3};
  v.reals.resize(element_count(v.shape));
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    data->GetPoint(i, &v.reals[3 * static_cast<std::size_t>(i)]);
  return v;
}

// The number of points every cell has, or 0 when they differ (or there are no cells).
std::size_t uniform_cell_size(const std::vector<std::int64_t>& offsets) {
  if (offsets.size() < 2) return 0;
  const std::int64_t size = offsets[1] - offsets[0];
  for (std::size_t c = 1; c + 1 < offsets.size(); ++c) {
    if (offsets[c + 1] - offsets[c] != size) return 0;
  }
  return static_cast<std::size_t>(size);
}

// Cell types and connectivity through the generic cell API: the same for grids and polydata.
void add_cells(FrameBlock& block, vtkDataSet* data) {
  const auto cells = static_cast<std::size_t>(data->GetNumberOfCells());
  ValueArray types{ValueKind::Integer, {cells}, {}, std::vector<std::int64_t>(cells), {}};
  ValueArray connectivity{ValueKind::Integer, {}, {}, {}, {}};
  ValueArray offsets{ValueKind::Integer, {cells + 1}, {}, {0}, {}};
  vtkNew<vtkIdList> ids;
  for (std::size_t c = 0; c < cells; ++c) {
    types.integers[c] = data->GetCellType(static_cast<vtkIdType>(c));
    data->GetCellPoints(static_cast<vtkIdType>(c), ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      connectivity.integers.push_back(ids->GetId(k));
    offsets.integers.push_back(static_cast<std::int64_t>(connectivity.integers.size()));
  }
  const std::size_t size = uniform_cell_size(offsets.integers);
  connectivity.shape = size > 0 ? Shape{cells, size} : Shape{connectivity.integers.size()};
  block.arrays.push_back({"cell types", {"cell"}, std::move(types)});
  block.arrays.push_back({"cell connectivity", size > 0 ? AxisNames{"cell", "vertex"} : AxisNames{},
                          std::move(connectivity)});
  // Cells of one size: the shape says where each starts. Otherwise the offsets do.
  if (size == 0) block.arrays.push_back({"cell offsets", {}, std::move(offsets)});
}

void add_arrays(FrameBlock& block, vtkFieldData* data, const std::string& kind,
                const AxisNames& axes) {
  if (data == nullptr) return;
  for (int i = 0; i < data->GetNumberOfArrays(); ++i) {
    vtkAbstractArray* array = data->GetAbstractArray(i);
    const char* name = array->GetName();
    const std::string label =
        kind + " array " + (name != nullptr ? name : unnamed(static_cast<std::size_t>(i)));
    block.arrays.push_back({label, axes, array_values(array, block.piece.string() + " " + label)});
  }
}

FrameBlock to_frame_block(const Piece& piece, const std::string& name, vtkDataSet* data) {
  FrameBlock block{name,
                   data->GetClassName(),
                   piece.file,
                   static_cast<std::size_t>(data->GetNumberOfPoints()),
                   static_cast<std::size_t>(data->GetNumberOfCells()),
                   {}};
  block.arrays.push_back(
      {"points", {"point", "component"}, point_values(data, piece.file.string())});
  add_cells(block, data);
  add_arrays(block, data->GetPointData(), "point", {"point", "component"});
  add_arrays(block, data->GetCellData(), "cell", {"cell", "component"});
  add_arrays(block, data->GetFieldData(), "field", {"tuple", "component"});
  return block;
}

std::string block_name(vtkMultiBlockDataSet* blocks, unsigned index, const Piece& piece) {
  if (blocks->HasMetaData(index) == 0) return piece.name;
  const char* name = blocks->GetMetaData(index)->Get(vtkCompositeDataSet::NAME());
  return name != nullptr ? name : piece.name;
}

// VTK hands back what it could read: the counts must be the ones the piece declares.
void check_counts(const Piece& piece, const fs::path& vtm, vtkDataSet* data) {
  if (data == nullptr)
    throw piece_error(piece, vtm, "VTK read no dataset from it (unreadable piece)");
  if (!piece.declared) return;
  if (data->GetNumberOfPoints() != piece.declared->points ||
      data->GetNumberOfCells() != piece.declared->cells) {
    throw piece_error(piece, vtm,
                      "VTK read " + std::to_string(data->GetNumberOfPoints()) + " points and " +
                          std::to_string(data->GetNumberOfCells()) +
                          " cells, but the file declares " +
                          std::to_string(piece.declared->points) + " and " +
                          std::to_string(piece.declared->cells) + " (truncated or corrupt file)");
  }
}

}  // namespace

std::vector<FrameBlock> read_vtm_frame(const fs::path& vtm) {
  std::vector<Piece> pieces = list_pieces(vtm);
  for (Piece& piece : pieces) check_piece(piece, vtm);
  const vtkSmartPointer<vtkMultiBlockDataSet> blocks = read_multiblock(vtm, pieces);
  if (blocks->GetNumberOfBlocks() != pieces.size()) {
    throw InputError(vtm.string() + ": VTK read " + std::to_string(blocks->GetNumberOfBlocks()) +
                     " blocks, but the file lists " + std::to_string(pieces.size()));
  }
  std::vector<FrameBlock> frame;
  for (unsigned i = 0; i < blocks->GetNumberOfBlocks(); ++i) {
    auto* data = vtkDataSet::SafeDownCast(blocks->GetBlock(i));
    check_counts(pieces[i], vtm, data);
    frame.push_back(to_frame_block(pieces[i], block_name(blocks, i, pieces[i]), data));
  }
  return frame;
}

}  // namespace mrsim
