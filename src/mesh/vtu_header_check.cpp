#include "mesh/vtu_header_check.hpp"

#include <cctype>
#include <charconv>
#include <climits>
#include <optional>
#include <string_view>
#include <vector>

#include "mesh/mesh_input.hpp"

namespace mrsim {
namespace {

struct FileInfo {
  std::string_view compressor;
  std::size_t header_bytes = 4;  // UInt32 or UInt64 block-size integers
  bool big_endian = false;       // byte_order="BigEndian"
};

// Value of `name="..."` inside one XML start tag ("" if absent).
std::string_view attribute(std::string_view tag, std::string_view name) {
  const std::string key = cat(" ", name, "=\"");
  const auto at = tag.find(key);
  if (at == std::string_view::npos) return {};
  const auto start = at + key.size();
  const auto end = tag.find('"', start);
  return end == std::string_view::npos ? std::string_view{} : tag.substr(start, end - start);
}

// The start tag beginning at `at` ("<DataArray ... >").
std::string_view tag_at(std::string_view xml, std::size_t at) {
  const auto end = xml.find('>', at);
  return xml.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at);
}

std::optional<std::int64_t> parse_count(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  std::int64_t n = -1;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc() || end != text.data() + text.size() || n < 0) return std::nullopt;
  return n;
}

// Sum of every Piece's `name`="N".
std::int64_t declared_total(std::string_view xml, std::string_view name, const std::filesystem::path& path) {
  std::int64_t total = 0;
  for (auto at = xml.find("<Piece"); at != std::string_view::npos; at = xml.find("<Piece", at + 1)) {
    const auto n = parse_count(attribute(tag_at(xml, at), name));
    if (!n || *n > INT_MAX || total + *n > INT_MAX)
      throw mesh_error(path, cat("invalid ", name, " attribute in the VTK XML header"));
    total += *n;
  }
  return total;
}

// Worst-case expansion of each compressor: more declared data than this cannot be honest.
double max_expansion(std::string_view compressor) {
  if (compressor.empty()) return 1;
  if (compressor == "vtkZLibDataCompressor") return 1100;
  if (compressor == "vtkLZ4DataCompressor") return 300;
  return 10000;  // LZMA can do better still; 1e4 keeps the bound finite
}

// ---- compressed block headers --------------------------------------------------------------

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

// Decodes up to `want` bytes from the start of a base64 text (stops at '=' or a non-base64
// character). Returns fewer bytes if the text is shorter.
std::string base64_prefix(std::string_view text, std::size_t want) {
  std::string out;
  unsigned buffer = 0;
  int bits = 0;
  for (char c : text) {
    const int v = base64_value(c);
    if (v < 0) break;
    buffer = (buffer << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((buffer >> bits) & 0xff));
      if (out.size() == want) break;
    }
  }
  return out;
}

// Where an array's encoded bytes live and how much the file holds after its start.
struct ArrayData {
  std::string_view text;  // from the array's first byte (raw) or character (base64) to file end
  bool base64 = false;
};

// The index-th header integer, assembled byte by byte in the file's byte order.
std::uint64_t read_uint(std::string_view bytes, std::size_t index, const FileInfo& f) {
  std::uint64_t v = 0;
  for (std::size_t b = 0; b < f.header_bytes; ++b) {
    const std::size_t byte = f.big_endian ? b : f.header_bytes - 1 - b;
    v = (v << 8) | static_cast<unsigned char>(bytes[index * f.header_bytes + byte]);
  }
  return v;
}

// VTK's compressed layout: [nblocks, block size, last block size, compressed size x nblocks],
// then the compressed blocks.
void check_compressed_array(const ArrayData& a, const FileInfo& f, double expansion, const std::string& name,
                            const std::filesystem::path& path) {
  const std::size_t h = f.header_bytes;
  const double available = a.base64 ? static_cast<double>(a.text.size()) * 3 / 4 : static_cast<double>(a.text.size());
  auto fail = [&](const std::string& what) {
    throw mesh_error(path, cat("compressed data array '", name, "' ", what, " (truncated or corrupt file)"));
  };
  std::string decoded;
  std::string_view header = a.text;
  if (a.base64) header = decoded = base64_prefix(a.text, 3 * h);
  if (header.size() < 3 * h) fail("has an incomplete block header");
  const std::uint64_t blocks = read_uint(header, 0, f);
  if (static_cast<double>(blocks) * static_cast<double>(h) > available)
    fail(cat("announces ", blocks, " blocks, more than the file holds"));
  const std::size_t header_size = (3 + static_cast<std::size_t>(blocks)) * h;
  if (a.base64) header = decoded = base64_prefix(a.text, header_size);
  if (header.size() < header_size) fail("has an incomplete block header");
  double compressed = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) compressed += static_cast<double>(read_uint(header, 3 + b, f));
  if (compressed > available) fail(cat("announces ", compressed, " compressed bytes, more than the file holds"));
  const double block = static_cast<double>(read_uint(header, 1, f));
  const double last = static_cast<double>(read_uint(header, 2, f));
  const double raw = blocks == 0 ? 0 : (static_cast<double>(blocks) - 1) * block + (last > 0 ? last : block);
  if (raw > compressed * expansion + 1024 || last > block)
    fail(cat("announces ", raw, " uncompressed bytes from ", compressed, " compressed ones"));
}

// Position of the '_' that precedes the appended data (npos without <AppendedData>). VTK
// does not look for the '_': it skips the blanks after the element's '>' and then one more
// character, whatever it is. Locate the data the same way, and require that character to be
// '_', or a stray byte would shift every offset (and VTK would read garbage block headers).
std::size_t appended_data_marker(std::string_view file, std::size_t appended_at, const std::filesystem::path& path) {
  if (appended_at == std::string_view::npos) return std::string_view::npos;
  auto p = file.find('>', appended_at);
  if (p != std::string_view::npos)
    for (++p; p < file.size() && std::isspace(static_cast<unsigned char>(file[p])); ) ++p;
  if (p == std::string_view::npos || p >= file.size() || file[p] != '_')
    throw mesh_error(path, "the appended data does not start with '_' (truncated or corrupt file)");
  return p;
}

// VTK reads a whitespace-only NumberOfComponents as an uninitialised count (a .vtu with
// NumberOfComponents="\n" kept it busy for a minute): accept plain positive integers only.
void check_components(std::string_view tag, const std::string& name, const std::filesystem::path& path) {
  constexpr std::int64_t kMaxComponents = 10000;
  const std::string_view text = attribute(tag, "NumberOfComponents");
  if (text.empty() && tag.find(" NumberOfComponents=") == std::string_view::npos) return;  // default 1
  const auto n = parse_count(text);
  if (!n || *n < 1 || *n > kMaxComponents)
    throw mesh_error(path, cat("data array '", name, "' has an invalid NumberOfComponents (corrupt file)"));
}

// Every DataArray: sane component count, appended data inside the file, and honest
// compression headers.
void check_data_arrays(std::string_view file, std::string_view xml, const FileInfo& f,
                       const std::filesystem::path& path) {
  const double expansion = max_expansion(f.compressor);
  const auto appended_at = file.find("<AppendedData");
  const std::string_view appended_tag = appended_at == std::string_view::npos ? "" : tag_at(file, appended_at);
  const auto underscore = appended_data_marker(file, appended_at, path);
  for (auto at = xml.find("<DataArray"); at != std::string_view::npos; at = xml.find("<DataArray", at + 1)) {
    const std::string_view tag = tag_at(xml, at);
    const std::string_view format = attribute(tag, "format");
    const std::string name(attribute(tag, "Name"));
    check_components(tag, name, path);
    ArrayData a;
    if (format == "binary") {
      auto start = at + tag.size() + 1;
      while (start < file.size() && (file[start] == ' ' || file[start] == '\n' || file[start] == '\r' || file[start] == '\t'))
        ++start;
      a = {file.substr(std::min(start, file.size())), true};
    } else if (format == "appended") {
      const auto offset = parse_count(attribute(tag, "offset"));
      if (underscore == std::string_view::npos || !offset || static_cast<std::uint64_t>(*offset) > file.size() - underscore - 1)
        throw mesh_error(path, cat("data array '", name, "' points outside the appended data (truncated or corrupt file)"));
      a = {file.substr(underscore + 1 + static_cast<std::size_t>(*offset)), attribute(appended_tag, "encoding") == "base64"};
    } else {
      continue;  // ascii: VTK parses it into arrays sized by the (already checked) counts
    }
    if (!f.compressor.empty()) check_compressed_array(a, f, expansion, name, path);
  }
}

}  // namespace

VtuDeclared check_vtu_header(const std::string& bytes, const std::filesystem::path& path) {
  const std::string_view file = bytes;
  const auto file_tag_at = file.find("<VTKFile");
  if (file_tag_at == std::string_view::npos || file_tag_at > 4096)
    throw mesh_error(path, "not a VTK XML file (no <VTKFile> element)");
  const std::string_view file_tag = tag_at(file, file_tag_at);
  const std::string_view type = attribute(file_tag, "type");
  if (type != "UnstructuredGrid")
    throw mesh_error(path, cat("holds VTK ", type.empty() ? "(unknown)" : std::string(type),
                               " data; mrsim reads tetrahedral meshes from UnstructuredGrid (.vtu) files"));
  const FileInfo info{attribute(file_tag, "compressor"), attribute(file_tag, "header_type") == "UInt64" ? 8u : 4u,
                      attribute(file_tag, "byte_order") == "BigEndian"};

  const std::string_view xml = file.substr(0, file.find("<AppendedData"));
  const VtuDeclared d{declared_total(xml, "NumberOfPoints", path), declared_total(xml, "NumberOfCells", path)};
  // At least 6 bytes per point ("0 0 0 ") and 4 per cell (an offset and a type), times what
  // compression can gain.
  const double room = static_cast<double>(bytes.size()) * max_expansion(info.compressor);
  if (6.0 * static_cast<double>(d.points) > room || 4.0 * static_cast<double>(d.cells) > room)
    throw mesh_error(path, cat("the header declares ", d.points, " points and ", d.cells, " cells, more than ",
                               bytes.size(), " bytes can hold: the counts are wrong or the file is truncated"));
  check_data_arrays(file, xml, info, path);
  return d;
}

}  // namespace mrsim
