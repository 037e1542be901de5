#include "mesh/vtu_header_check.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "mesh/mesh_input.hpp"

namespace mrsim {
namespace {

struct FileInfo {
  std::string_view compressor;
  std::size_t header_bytes = 4;  // UInt32 or UInt64 block-size integers
  bool big_endian = false;       // byte_order="BigEndian"
};

// The whitespace of XML, and of VTK's scans for inline and appended data (vtkXMLParser::IsSpace).
bool is_xml_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// One XML start tag, with its attributes as written (entity references not decoded).
struct StartTag {
  std::size_t at = 0;  // position of its '<'
  std::string_view name;
  std::vector<std::pair<std::string_view, std::string_view>> attributes;

  std::optional<std::string_view> get(std::string_view attribute) const {
    for (const auto& [n, v] : attributes)
      if (n == attribute) return v;
    return std::nullopt;
  }
};

// Every start tag of `xml` in order; comments, processing instructions, CDATA sections,
// declarations and end tags are skipped as an XML parser skips them. VTK applies a tag's
// attributes whatever the tag is called (the first element inside <Points> is read as the
// points array by position, "Array" is as good as "DataArray") and however they are spaced
// (tabs, newlines, single quotes, '>' inside a value): looking only for `<DataArray` and
// ` name="` let misspelt or oddly spaced arrays reach VTK unchecked (mesh fuzzer, issue 18).
// Malformed tags are read as far as they go: expat refuses the file before VTK reads any data.
std::vector<StartTag> start_tags(std::string_view xml) {
  std::vector<StartTag> tags;
  const auto skip_past = [&](std::size_t from, std::string_view end) {
    const auto found = xml.find(end, from);
    return found == std::string_view::npos ? xml.size() : found + end.size();
  };
  std::size_t i = 0;
  while ((i = xml.find('<', i)) != std::string_view::npos) {
    const std::string_view rest = xml.substr(i);
    if (rest.starts_with("<!--")) {
      i = skip_past(i + 4, "-->");
    } else if (rest.starts_with("<![CDATA[")) {
      i = skip_past(i + 9, "]]>");
    } else if (rest.starts_with("<?")) {
      i = skip_past(i + 2, "?>");
    } else if (rest.starts_with("<!") || rest.starts_with("</")) {
      i = skip_past(i + 2, ">");
    } else {
      StartTag tag;
      tag.at = i++;
      const auto word_end = [&](std::size_t from) {
        while (from < xml.size() && !is_xml_space(xml[from]) && xml[from] != '=' &&
               xml[from] != '>' && xml[from] != '/')
          ++from;
        return from;
      };
      std::size_t end = word_end(i);
      tag.name = xml.substr(i, end - i);
      i = end;
      while (i < xml.size()) {
        while (i < xml.size() && is_xml_space(xml[i])) ++i;
        if (i >= xml.size()) break;
        if (xml[i] == '>') {
          ++i;
          break;
        }
        end = word_end(i);
        if (end == i) {  // a '/' of "/>", or a stray '='
          ++i;
          continue;
        }
        const std::string_view attribute = xml.substr(i, end - i);
        for (i = end; i < xml.size() && is_xml_space(xml[i]);) ++i;
        if (i >= xml.size() || xml[i] != '=') continue;
        for (++i; i < xml.size() && is_xml_space(xml[i]);) ++i;
        if (i >= xml.size() || (xml[i] != '"' && xml[i] != '\'')) continue;
        const auto close = xml.find(xml[i], i + 1);
        const auto value_end = close == std::string_view::npos ? xml.size() : close;
        tag.attributes.emplace_back(attribute, xml.substr(i + 1, value_end - i - 1));
        i = std::min(xml.size(), value_end + 1);
      }
      tags.push_back(std::move(tag));
    }
  }
  return tags;
}

// The value of an attribute mrsim interprets, "" if absent. Expat decodes entity and
// character references ("&#48;" is "0") before VTK sees a value; no writer uses them in
// these attributes, so rather than decode them, refuse them.
std::string_view plain_attribute(const StartTag& tag, std::string_view attribute,
                                 const std::filesystem::path& path) {
  const std::string_view value = tag.get(attribute).value_or("");
  if (value.find('&') != std::string_view::npos)
    throw mesh_error(path, cat("the ", attribute, " attribute of ", quoted_token(tag.name),
                               " holds an XML reference ('&'), which mrsim does not read "
                               "(corrupt file?)"));
  return value;
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
std::int64_t declared_total(const std::vector<StartTag>& tags, std::string_view name,
                            const std::filesystem::path& path) {
  std::int64_t total = 0;
  for (const StartTag& tag : tags) {
    if (tag.name != "Piece") continue;
    const auto n = parse_count(plain_attribute(tag, name, path));
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
void check_compressed_array(const ArrayData& a, const FileInfo& f, double expansion,
                            const std::string& name, const std::filesystem::path& path) {
  const std::size_t h = f.header_bytes;
  const double available =
      a.base64 ? static_cast<double>(a.text.size()) * 3 / 4 : static_cast<double>(a.text.size());
  auto fail = [&](const std::string& what) {
    throw mesh_error(
        path, cat("compressed data array '", name, "' ", what, " (truncated or corrupt file)"));
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
  for (std::uint64_t b = 0; b < blocks; ++b)
    compressed += static_cast<double>(read_uint(header, 3 + b, f));
  if (compressed > available)
    fail(cat("announces ", compressed, " compressed bytes, more than the file holds"));
  const double block = static_cast<double>(read_uint(header, 1, f));
  const double last = static_cast<double>(read_uint(header, 2, f));
  // VTK sizes the data as blocks * block - block + last when last > 0: with no blocks that
  // wraps around to ~2^64 bytes, and it then reads block 0 from its empty (null) table of
  // block sizes and crashes (found by the mesh fuzzer, issue 18).
  if (blocks == 0 && last > 0)
    fail(cat("announces a last block of ", last, " bytes but no blocks"));
  const double raw =
      blocks == 0 ? 0 : (static_cast<double>(blocks) - 1) * block + (last > 0 ? last : block);
  if (raw > compressed * expansion + 1024 || last > block)
    fail(cat("announces ", raw, " uncompressed bytes from ", compressed, " compressed ones"));
}

// Position of the '_' that precedes the appended data (npos without <AppendedData>). VTK
// does not look for the '_': it skips the blanks after the element's '>' and then one more
// character, whatever it is. Locate the data the same way, and require that character to be
// '_', or a stray byte would shift every offset (and VTK would read garbage block headers).
// The blanks are VTK's four: skipping any other byte (a '\v') would put the data elsewhere
// than VTK does.
std::size_t appended_data_marker(std::string_view file, std::size_t appended_at,
                                 const std::filesystem::path& path) {
  if (appended_at == std::string_view::npos) return std::string_view::npos;
  auto p = file.find('>', appended_at);
  if (p != std::string_view::npos)
    for (++p; p < file.size() && is_xml_space(file[p]);) ++p;
  if (p == std::string_view::npos || p >= file.size() || file[p] != '_')
    throw mesh_error(path, "the appended data does not start with '_' (truncated or corrupt file)");
  return p;
}

// VTK reads a whitespace-only NumberOfComponents as an uninitialised count, and an overflowing
// one as INT_MAX, then loops over that many component names (a .vtu with NumberOfComponents=
// "\n" kept it busy for a minute): accept plain positive integers only.
void check_components(const StartTag& tag, const std::string& name,
                      const std::filesystem::path& path) {
  constexpr std::int64_t kMaxComponents = 10000;
  if (!tag.get("NumberOfComponents")) return;  // default 1
  const auto n = parse_count(plain_attribute(tag, "NumberOfComponents", path));
  if (!n || *n < 1 || *n > kMaxComponents)
    throw mesh_error(
        path, cat("data array '", name, "' has an invalid NumberOfComponents (corrupt file)"));
}

// Every element's arrays as VTK reads them: sane component count, appended data inside the
// file, and honest compression headers. VTK reads appended data whenever an element has an
// offset, whatever its format says (format="ascii" with an offset and a corrupt block header
// crashed it), and inline binary data only for format="binary" exactly; anything else it
// parses as ascii text into arrays sized by the (already checked) counts.
void check_data_arrays(std::string_view file, const std::vector<StartTag>& tags, const FileInfo& f,
                       const std::filesystem::path& path) {
  const double expansion = max_expansion(f.compressor);
  const auto appended_at = file.find("<AppendedData");
  const auto underscore = appended_data_marker(file, appended_at, path);
  bool appended_base64 = false;
  if (appended_at != std::string_view::npos) {
    const auto appended_tags = start_tags(file.substr(appended_at, underscore - appended_at));
    // VTK decodes base64 unless the encoding is exactly "raw".
    appended_base64 =
        appended_tags.empty() || plain_attribute(appended_tags[0], "encoding", path) != "raw";
  }
  for (const StartTag& tag : tags) {
    const std::string name(tag.get("Name").value_or(""));
    check_components(tag, name, path);
    ArrayData a;
    if (tag.get("offset")) {
      const auto offset = parse_count(plain_attribute(tag, "offset", path));
      if (underscore == std::string_view::npos || !offset ||
          static_cast<std::uint64_t>(*offset) > file.size() - underscore - 1)
        throw mesh_error(path,
                         cat("data array '", name,
                             "' points outside the appended data (truncated or corrupt file)"));
      a = {file.substr(underscore + 1 + static_cast<std::size_t>(*offset)), appended_base64};
    } else if (plain_attribute(tag, "format", path) == "binary") {
      // VTK's inline data starts after the first '>' from the tag start and its blanks.
      auto start = file.find('>', tag.at);
      start = start == std::string_view::npos ? file.size() : start + 1;
      while (start < file.size() && is_xml_space(file[start])) ++start;
      a = {file.substr(start), true};
    } else {
      continue;
    }
    if (!f.compressor.empty()) check_compressed_array(a, f, expansion, name, path);
  }
}

}  // namespace

VtuDeclared check_vtu_header(const std::string& bytes, const std::filesystem::path& path) {
  const std::string_view file = bytes;
  // VTK's XML parser stops at the first "<AppendedData", wherever it is: so do the checks.
  const std::vector<StartTag> tags = start_tags(file.substr(0, file.find("<AppendedData")));
  if (tags.empty() || tags[0].name != "VTKFile")
    throw mesh_error(path, "not a VTK XML file (no <VTKFile> element)");
  const StartTag& file_tag = tags[0];
  const std::string_view type = plain_attribute(file_tag, "type", path);
  if (type != "UnstructuredGrid")
    throw mesh_error(
        path, cat("holds VTK ", type.empty() ? "(unknown)" : std::string(type),
                  " data; mrsim reads tetrahedral meshes from UnstructuredGrid (.vtu) files"));
  const FileInfo info{plain_attribute(file_tag, "compressor", path),
                      plain_attribute(file_tag, "header_type", path) == "UInt64" ? 8u : 4u,
                      plain_attribute(file_tag, "byte_order", path) == "BigEndian"};

  const VtuDeclared d{declared_total(tags, "NumberOfPoints", path),
                      declared_total(tags, "NumberOfCells", path)};
  // At least 6 bytes per point ("0 0 0 ") and 4 per cell (an offset and a type), times what
  // compression can gain.
  const double room = static_cast<double>(bytes.size()) * max_expansion(info.compressor);
  if (6.0 * static_cast<double>(d.points) > room || 4.0 * static_cast<double>(d.cells) > room)
    throw mesh_error(
        path, cat("the header declares ", d.points, " points and ", d.cells, " cells, more than ",
                  bytes.size(), " bytes can hold: the counts are wrong or the file is truncated"));
  check_data_arrays(file, tags, info, path);
  return d;
}

}  // namespace mrsim
