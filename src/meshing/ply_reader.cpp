// PLY (Stanford polygon format), ascii and binary little/big endian. The header declares
// elements and their properties; "vertex" gives x y z, "face" a list property named
// vertex_indices (or vertex_index). Other elements and properties are read and ignored, so
// the reader walks binary data of any layout.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

#include "core/error.hpp"
#include "meshing/surface_readers.hpp"
#include "meshing/text_lines.hpp"

namespace mrsim {
namespace {

enum class PlyFormat { Ascii, BinaryLittle, BinaryBig };

struct PlyProperty {
  std::string name;
  std::string type;        // scalar type, or the item type of a list
  std::string count_type;  // empty for a scalar
};

struct PlyElement {
  std::string name;
  std::int64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;
};

std::size_t type_size(const std::string& type) {
  static const std::array<std::pair<const char*, std::size_t>, 16> sizes{{
      {"char", 1}, {"uchar", 1}, {"int8", 1}, {"uint8", 1}, {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2}, {"int", 4}, {"uint", 4}, {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}}};
  for (const auto& [name, size] : sizes) {
    if (type == name) return size;
  }
  return 0;
}

void parse_property(const TextLines& lines, PlyHeader& header) {
  if (header.elements.empty()) lines.fail("'property' before any 'element'");
  const auto& t = lines.tokens();
  PlyProperty p;
  if (t.size() == 5 && t[1] == "list") {
    p = {std::string(t[4]), std::string(t[3]), std::string(t[2])};
    if (type_size(p.count_type) == 0) lines.fail("unknown type '" + p.count_type + "'");
  } else if (t.size() == 3) {
    p = {std::string(t[2]), std::string(t[1]), ""};
  } else {
    lines.fail("malformed property declaration");
  }
  if (type_size(p.type) == 0) lines.fail("unknown type '" + p.type + "'");
  header.elements.back().properties.push_back(p);
}

void parse_format(const TextLines& lines, PlyHeader& header) {
  const auto& t = lines.tokens();
  if (t.size() < 2) lines.fail("malformed format line");
  if (t[1] == "ascii") header.format = PlyFormat::Ascii;
  else if (t[1] == "binary_little_endian") header.format = PlyFormat::BinaryLittle;
  else if (t[1] == "binary_big_endian") header.format = PlyFormat::BinaryBig;
  else lines.fail("unknown PLY format '" + std::string(t[1]) + "'");
}

PlyHeader parse_header(TextLines& lines) {
  if (!lines.next() || lines.tokens()[0] != "ply") lines.fail_file("not a PLY file (no 'ply' magic)");
  PlyHeader header;
  while (lines.next()) {
    const std::string_view keyword = lines.tokens()[0];
    if (keyword == "end_header") {
      header.data_offset = lines.end_offset();
      return header;
    }
    if (keyword == "format") parse_format(lines, header);
    else if (keyword == "element") {
      const std::int64_t count = lines.integer(2);
      if (count < 0) lines.fail("negative element count");
      header.elements.push_back({std::string(lines.tokens()[1]), count, {}});
    } else if (keyword == "property") parse_property(lines, header);
    // comment and obj_info lines carry nothing the mesher needs
  }
  lines.fail_file("header has no 'end_header'");
}

/// Reads the values of one element instance, property by property; a list property gives its
/// items (without the count).
class PlyValues {
 public:
  PlyValues(const std::string& bytes, const PlyHeader& header, const std::filesystem::path& path)
      : bytes_(bytes), format_(header.format), path_(path), pos_(header.data_offset),
        lines_(std::string_view(bytes).substr(header.data_offset), path, '\0') {}

  std::vector<std::vector<double>> element(const PlyElement& e) {
    std::vector<std::vector<double>> values;
    if (format_ == PlyFormat::Ascii) return ascii_element(e);
    for (const PlyProperty& p : e.properties) {
      std::vector<double> items;
      const std::size_t n = p.count_type.empty() ? 1 : count(binary(p.count_type));
      for (std::size_t k = 0; k < n; ++k) items.push_back(binary(p.type));
      values.push_back(std::move(items));
    }
    return values;
  }

 private:
  std::vector<std::vector<double>> ascii_element(const PlyElement& e) {
    if (!lines_.next()) throw InputError(path_.string() + ": data ends before every '" + e.name + "' is read");
    std::vector<std::vector<double>> values;
    std::size_t t = 0;
    for (const PlyProperty& p : e.properties) {
      std::vector<double> items;
      const std::size_t n = p.count_type.empty() ? 1 : count(lines_.real(t++));
      for (std::size_t k = 0; k < n; ++k) items.push_back(lines_.real(t++));
      values.push_back(std::move(items));
    }
    return values;
  }

  std::size_t count(double value) const {
    if (!(value >= 0.0 && value <= 1.0e6)) throw InputError(path_.string() + ": bad list length in PLY data");
    return static_cast<std::size_t>(value);
  }

  double binary(const std::string& type) {
    const std::size_t size = type_size(type);
    if (pos_ + size > bytes_.size()) throw InputError(path_.string() + ": binary data is truncated");
    std::array<char, 8> raw{};
    std::memcpy(raw.data(), bytes_.data() + pos_, size);
    pos_ += size;
    if (format_ == PlyFormat::BinaryBig) std::reverse(raw.begin(), raw.begin() + size);
    return decode(type, raw.data());
  }

  static double decode(const std::string& type, const char* raw) {
    auto as = [raw](auto value) { std::memcpy(&value, raw, sizeof value); return static_cast<double>(value); };
    if (type == "char" || type == "int8") return as(std::int8_t{});
    if (type == "uchar" || type == "uint8") return as(std::uint8_t{});
    if (type == "short" || type == "int16") return as(std::int16_t{});
    if (type == "ushort" || type == "uint16") return as(std::uint16_t{});
    if (type == "int" || type == "int32") return as(std::int32_t{});
    if (type == "uint" || type == "uint32") return as(std::uint32_t{});
    if (type == "float" || type == "float32") return as(float{});
    return as(double{});
  }

  const std::string& bytes_;
  PlyFormat format_;
  std::filesystem::path path_;
  std::size_t pos_;
  TextLines lines_;
};

int property_index(const PlyElement& e, std::initializer_list<const char*> names) {
  for (std::size_t i = 0; i < e.properties.size(); ++i) {
    for (const char* name : names) {
      if (e.properties[i].name == name) return static_cast<int>(i);
    }
  }
  return -1;
}

void read_vertices(PlyValues& values, const PlyElement& e, SurfaceMesh& surface,
                   const std::filesystem::path& path) {
  const int x = property_index(e, {"x"}), y = property_index(e, {"y"}), z = property_index(e, {"z"});
  if (x < 0 || y < 0 || z < 0) throw InputError(path.string() + ": PLY vertices lack x, y or z");
  for (std::int64_t i = 0; i < e.count; ++i) {
    const auto v = values.element(e);
    surface.points.emplace_back(v[x][0], v[y][0], v[z][0]);
  }
}

void read_faces(PlyValues& values, const PlyElement& e, SurfaceMesh& surface,
                const std::filesystem::path& path) {
  const int list = property_index(e, {"vertex_indices", "vertex_index"});
  if (list < 0 || e.properties[list].count_type.empty()) {
    throw InputError(path.string() + ": PLY faces lack a vertex_indices list");
  }
  for (std::int64_t f = 0; f < e.count; ++f) {
    const auto v = values.element(e);
    std::vector<int> corners;
    for (double index : v[list]) {
      if (!(index >= 0.0 && index < static_cast<double>(surface.points.size()))) {
        throw InputError(path.string() + ": face " + std::to_string(f + 1) + " refers to vertex " +
                         std::to_string(index) + ", out of range");
      }
      corners.push_back(static_cast<int>(index));
    }
    if (corners.size() < 3) {
      throw InputError(path.string() + ": face " + std::to_string(f + 1) + " has fewer than 3 vertices");
    }
    add_polygon(surface, corners, static_cast<int>(f + 1));
  }
}

}  // namespace

SurfaceMesh read_ply(const std::string& bytes, const std::filesystem::path& path) {
  TextLines lines(bytes, path, '\0');
  const PlyHeader header = parse_header(lines);
  PlyValues values(bytes, header, path);
  SurfaceMesh surface;
  for (const PlyElement& e : header.elements) {
    if (e.name == "vertex") read_vertices(values, e, surface, path);
    else if (e.name == "face") read_faces(values, e, surface, path);
    else for (std::int64_t i = 0; i < e.count; ++i) values.element(e);
  }
  return surface;
}

}  // namespace mrsim
