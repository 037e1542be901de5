#include "io/vtk_xml_piece.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataCompressor.h>
#include <vtkDataSetAttributes.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkType.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string_view>

#include "core/error.hpp"

namespace mrsim {
namespace {

constexpr std::size_t kBlockSize = 32768;  // vtkXMLWriter's BlockSize: bytes per compressed block
constexpr std::size_t kReserved = 20;      // vtkXMLWriter::ReserveAttributeSpace's default width

static_assert(sizeof(long) == 8, "VTK_LONG is written as Int64 on LP64 platforms only");
static_assert(std::endian::native == std::endian::little,
              "pieces are declared LittleEndian and hold the values as in memory");

// The XML word type of a VTK data type, nullptr for those left to VTK's writer.
const char* word_type(int type) {
  switch (type) {
    case VTK_DOUBLE: return "Float64";
    case VTK_FLOAT: return "Float32";
    case VTK_SIGNED_CHAR: return "Int8";
    case VTK_UNSIGNED_CHAR: return "UInt8";
    case VTK_SHORT: return "Int16";
    case VTK_UNSIGNED_SHORT: return "UInt16";
    case VTK_INT: return "Int32";
    case VTK_UNSIGNED_INT: return "UInt32";
    case VTK_LONG:
    case VTK_LONG_LONG: return "Int64";
    case VTK_UNSIGNED_LONG:
    case VTK_UNSIGNED_LONG_LONG: return "UInt64";
    default: return nullptr;  // vtkIdType (an IdType attribute), char, bit, string arrays
  }
}

// Characters VTK's writer would write as they are, unescaped, into an attribute.
bool plain_text(const char* text) {
  return text != nullptr && *text != '\0' && std::strpbrk(text, "\"&<>") == nullptr;
}

// One array of the piece, in the order of the file, and what its header says of it.
struct Item {
  vtkDataArray* array = nullptr;
  const char* name = nullptr;
  const char* type = nullptr;
  const char* tag = nullptr;  // the section it opens ("Points", "Verts"...), if any
  bool tuples = false;        // NumberOfTuples written (field data)
  bool ranged = true;         // RangeMin / RangeMax filled (not for cells)
  bool skip_first = false;    // a cell array's offsets: VTK writes them without the leading 0
  double range[2] = {0, 0};
};

// vtkDataArray::GetRange(-1) as VTK computes it: the component's for one component, the
// Euclidean norm's for more (squared sums in component order, their root at the end). False for
// a value that is not finite: VTK skips NaN, this writer leaves those arrays to VTK's.
template <class T>
bool range_of(const T* values, vtkIdType tuples, int components, double range[2]) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (vtkIdType t = 0; t < tuples; ++t) {
    const T* v = values + t * components;
    double x = static_cast<double>(v[0]);
    if (components > 1) {
      x *= x;
      for (int c = 1; c < components; ++c)
        x += static_cast<double>(v[c]) * static_cast<double>(v[c]);
    }
    if (!std::isfinite(x)) return false;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  range[0] = components > 1 ? std::sqrt(lo) : lo;
  range[1] = components > 1 ? std::sqrt(hi) : hi;
  return true;
}

bool array_range(vtkDataArray* a, double range[2]) {
  const vtkIdType n = a->GetNumberOfTuples();
  const int k = a->GetNumberOfComponents();
  const void* p = a->GetVoidPointer(0);
  switch (a->GetDataType()) {
    case VTK_DOUBLE: return range_of(static_cast<const double*>(p), n, k, range);
    case VTK_FLOAT: return range_of(static_cast<const float*>(p), n, k, range);
    case VTK_SIGNED_CHAR: return range_of(static_cast<const signed char*>(p), n, k, range);
    case VTK_UNSIGNED_CHAR: return range_of(static_cast<const unsigned char*>(p), n, k, range);
    case VTK_SHORT: return range_of(static_cast<const short*>(p), n, k, range);
    case VTK_UNSIGNED_SHORT: return range_of(static_cast<const unsigned short*>(p), n, k, range);
    case VTK_INT: return range_of(static_cast<const int*>(p), n, k, range);
    case VTK_UNSIGNED_INT: return range_of(static_cast<const unsigned*>(p), n, k, range);
    case VTK_LONG: return range_of(static_cast<const long*>(p), n, k, range);
    case VTK_LONG_LONG: return range_of(static_cast<const long long*>(p), n, k, range);
    case VTK_UNSIGNED_LONG: return range_of(static_cast<const unsigned long*>(p), n, k, range);
    case VTK_UNSIGNED_LONG_LONG:
      return range_of(static_cast<const unsigned long long*>(p), n, k, range);
    default: return false;
  }
}

// An array this writer writes as VTK would: named, of a plain type, an array of structures
// without information keys. `ranged` arrays also hold at least one tuple, all finite.
bool plain_array(vtkDataArray* a, bool ranged) {
  if (a == nullptr || word_type(a->GetDataType()) == nullptr || !a->HasStandardMemoryLayout())
    return false;
  if (a->HasInformation() && a->GetInformation()->GetNumberOfKeys() > 0) return false;
  for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    if (a->GetComponentName(c) != nullptr && !plain_text(a->GetComponentName(c))) return false;
  if (!ranged) return true;
  return plain_text(a->GetName()) && a->GetNumberOfTuples() > 0;
}

// A data array with its range (field, point and cell data, the points), opening section `tag`.
bool add_ranged(std::vector<Item>& items, vtkDataArray* a, bool tuples, const char* tag) {
  Item item{a, nullptr, nullptr, tag, tuples};
  if (!plain_array(a, true) || !array_range(a, item.range)) return false;
  item.name = a->GetName();
  item.type = word_type(a->GetDataType());
  items.push_back(item);
  return true;
}

bool add_data(std::vector<Item>& items, vtkFieldData* data, bool tuples) {
  for (int i = 0; i < data->GetNumberOfArrays(); ++i)
    if (!add_ranged(items, vtkDataArray::SafeDownCast(data->GetAbstractArray(i)), tuples, nullptr))
      return false;
  return true;
}

bool add_cells(std::vector<Item>& items, vtkCellArray* cells, const char* tag) {
  if (cells == nullptr) return false;
  vtkDataArray* connectivity = cells->GetConnectivityArray();
  vtkDataArray* offsets = cells->GetOffsetsArray();
  if (!plain_array(connectivity, false) || !plain_array(offsets, false) ||
      offsets->GetNumberOfTuples() < 1)
    return false;
  items.push_back({connectivity, "connectivity", word_type(connectivity->GetDataType()), tag,
                   false, false});
  items.push_back({offsets, "offsets", word_type(offsets->GetDataType()), nullptr, false, false,
                   true});
  return true;
}

void attribute(std::string& s, std::string_view name, std::string_view value) {
  s += ' ';
  s += name;
  s += "=\"";
  s += value;
  s += '"';
}

// An attribute VTK reserves room for and fills in once the data are written: the value, then
// spaces up to the reserved width.
void reserved(std::string& s, std::string_view name, std::string_view value) {
  attribute(s, name, value);
  if (value.size() < kReserved) s.append(kReserved - value.size(), ' ');
}

// A double as VTK's stream writes it (precision 11, general notation).
std::string_view number(double x, std::array<char, 40>& buffer) {
  const int n = std::snprintf(buffer.data(), buffer.size(), "%.11g", x);
  return {buffer.data(), static_cast<std::size_t>(n)};
}

// <PointData Vectors="displacement"> and the like: the active attributes, in VTK's order.
void attributes_tag(std::string& s, const char* tag, vtkDataSetAttributes* data) {
  s += tag;
  std::array<int, vtkDataSetAttributes::NUM_ATTRIBUTES> active{};
  data->GetAttributeIndices(active.data());
  for (int i = 0; i < vtkDataSetAttributes::NUM_ATTRIBUTES; ++i)
    if (active[i] >= 0)
      attribute(s, vtkDataSetAttributes::GetAttributeTypeAsString(i),
                data->GetAbstractArray(active[i])->GetName());
  s += ">\n";
}

bool plain_attributes(vtkDataSetAttributes* data) {
  std::array<int, vtkDataSetAttributes::NUM_ATTRIBUTES> active{};
  data->GetAttributeIndices(active.data());
  for (const int index : active)
    if (index >= 0 && !plain_text(data->GetAbstractArray(index)->GetName())) return false;
  return true;
}

// Every array of the piece in the file's order, each checked and its range taken, and where its
// sections begin; false for a block left to VTK's writer.
struct Layout {
  std::vector<Item> items;
  std::size_t point_data = 0, cell_data = 0;  // where the point and cell data begin
};

bool collect(vtkPointSet* set, Layout& layout) {
  std::vector<Item>& items = layout.items;
  auto* grid = vtkUnstructuredGrid::SafeDownCast(set);
  auto* poly = vtkPolyData::SafeDownCast(set);
  if ((grid == nullptr && poly == nullptr) || set->GetPoints() == nullptr ||
      !plain_attributes(set->GetPointData()) || !plain_attributes(set->GetCellData()))
    return false;
  items.clear();
  if (!add_data(items, set->GetFieldData(), true)) return false;
  layout.point_data = items.size();
  if (!add_data(items, set->GetPointData(), false)) return false;
  layout.cell_data = items.size();
  if (!add_data(items, set->GetCellData(), false)) return false;
  if (!add_ranged(items, set->GetPoints()->GetData(), false, "Points")) return false;
  if (grid != nullptr) {
    vtkUnsignedCharArray* types = grid->GetCellTypesArray();
    if (grid->GetFaces() != nullptr || !add_cells(items, grid->GetCells(), "Cells") ||
        !plain_array(types, false))
      return false;
    items.push_back({types, "types", word_type(types->GetDataType()), nullptr, false, false});
    return true;
  }
  return add_cells(items, poly->GetVerts(), "Verts") &&
         add_cells(items, poly->GetLines(), "Lines") &&
         add_cells(items, poly->GetStrips(), "Strips") &&
         add_cells(items, poly->GetPolys(), "Polys");
}

// <Piece NumberOfPoints=... > with the counts VTK reserves room for.
void piece_tag(std::string& out, vtkPointSet* set) {
  out += "    <Piece";
  reserved(out, "NumberOfPoints", std::to_string(set->GetNumberOfPoints()));
  if (auto* poly = vtkPolyData::SafeDownCast(set)) {
    reserved(out, "NumberOfVerts", std::to_string(poly->GetNumberOfVerts()));
    reserved(out, "NumberOfLines", std::to_string(poly->GetNumberOfLines()));
    reserved(out, "NumberOfStrips", std::to_string(poly->GetNumberOfStrips()));
    reserved(out, "NumberOfPolys", std::to_string(poly->GetNumberOfPolys()));
  } else {
    reserved(out, "NumberOfCells", std::to_string(set->GetNumberOfCells()));
  }
  out += ">\n";
}

// <DataArray type=... Name=... ... RangeMin=... RangeMax=... offset=.../> at `offset` of the
// appended data.
void array_tag(std::string& out, const char* indent, const Item& item, std::size_t offset) {
  std::array<char, 40> buffer{};
  vtkDataArray* a = item.array;
  out += indent;
  out += "<DataArray";
  attribute(out, "type", item.type);
  attribute(out, "Name", item.name);
  if (a->GetNumberOfComponents() > 1)
    attribute(out, "NumberOfComponents", std::to_string(a->GetNumberOfComponents()));
  for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    if (a->GetComponentName(c) != nullptr)
      attribute(out, "ComponentName" + std::to_string(c), a->GetComponentName(c));
  if (item.tuples) attribute(out, "NumberOfTuples", std::to_string(a->GetNumberOfTuples()));
  out += " format=\"appended\"";
  reserved(out, "RangeMin", item.ranged ? number(item.range[0], buffer) : "");
  reserved(out, "RangeMax", item.ranged ? number(item.range[1], buffer) : "");
  reserved(out, "offset", std::to_string(offset));
  out += "/>\n";
}

}  // namespace

// One array's appended data as vtkXMLWriter lays it out: raw, a UInt64 byte count and the bytes;
// compressed, the header [blocks, block size, size of a partial last block or 0, each block's
// compressed size] and the blocks, each of kBlockSize bytes but the last.
void VtkXmlPiece::append(const unsigned char* bytes, std::size_t size,
                         vtkDataCompressor* compressor) {
  auto put = [&](std::uint64_t word) {
    data_.append(reinterpret_cast<const char*>(&word), sizeof word);
  };
  if (compressor == nullptr) {
    put(size);
    data_.append(reinterpret_cast<const char*>(bytes), size);
    return;
  }
  const std::size_t blocks = size / kBlockSize + (size % kBlockSize != 0 ? 1 : 0);
  put(blocks);
  put(kBlockSize);
  put(size % kBlockSize);
  const std::size_t sizes = data_.size();
  data_.append(blocks * sizeof(std::uint64_t), '\0');
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t raw = std::min(kBlockSize, size - b * kBlockSize);
    packed_.resize(compressor->GetMaximumCompressionSpace(raw));
    const std::size_t n =
        compressor->Compress(bytes + b * kBlockSize, raw, packed_.data(), packed_.size());
    if (n == 0) throw RunError("cannot compress a frame's data with " +
                               std::string(compressor->GetClassName()));
    const std::uint64_t word = n;
    std::memcpy(data_.data() + sizes + b * sizeof word, &word, sizeof word);
    data_.append(reinterpret_cast<const char*>(packed_.data()), n);
  }
}

bool VtkXmlPiece::write(vtkDataObject* block, vtkDataCompressor* compressor, std::string& out) {
  auto* set = vtkPointSet::SafeDownCast(block);
  Layout layout;
  if (set == nullptr || !collect(set, layout)) return false;
  const std::vector<Item>& items = layout.items;
  const char* kind = vtkPolyData::SafeDownCast(set) != nullptr ? "PolyData" : "UnstructuredGrid";
  out.clear();
  out += "<VTKFile";
  attribute(out, "type", kind);
  out += " version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"";
  if (compressor != nullptr) attribute(out, "compressor", compressor->GetClassName());
  out += ">\n  <";
  out += kind;
  out += ">\n";
  data_.clear();
  const char* open = nullptr;  // the section the next one closes
  auto close = [&](const char* indent) {
    if (open != nullptr) out += std::string(indent) + "</" + open + ">\n";
    open = nullptr;
  };
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Item& item = items[i];
    if (i == 0 && layout.point_data > 0) {
      out += "    <FieldData>\n";
      open = "FieldData";
    }
    if (i == layout.point_data) {
      close("    ");
      piece_tag(out, set);
      attributes_tag(out, "      <PointData", set->GetPointData());
      open = "PointData";
    }
    if (i == layout.cell_data) {
      close("      ");
      attributes_tag(out, "      <CellData", set->GetCellData());
      open = "CellData";
    }
    if (item.tag != nullptr) {
      close("      ");
      out += std::string("      <") + item.tag + ">\n";
      open = item.tag;
    }
    array_tag(out, i < layout.point_data ? "      " : "        ", item, data_.size());
    const std::size_t word = static_cast<std::size_t>(item.array->GetDataTypeSize());
    const std::size_t first = item.skip_first ? 1 : 0;
    const std::size_t values = static_cast<std::size_t>(item.array->GetNumberOfValues()) - first;
    append(static_cast<const unsigned char*>(item.array->GetVoidPointer(0)) + first * word,
           values * word, compressor);
  }
  close("      ");
  out += std::string("    </Piece>\n  </") + kind + ">\n  <AppendedData encoding=\"raw\">\n   _";
  out += data_;
  out += "\n  </AppendedData>\n</VTKFile>\n";
  return true;
}

}  // namespace mrsim
