#include "io/pvd_file.hpp"

#include <string_view>

#include "io/exact_number.hpp"

namespace mrsim {
namespace {

// File names are ours (frames/frame_NNNNNN.vtm), but escape anyway so the XML stays valid.
std::string xml_escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

std::string pvd_text(std::span<const PvdEntry> entries) {
  std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const PvdEntry& entry : entries) {
    text += "    <DataSet timestep=\"" + exact_number(entry.time) +
            "\" group=\"\" part=\"0\" file=\"" + xml_escaped(entry.file) + "\"/>\n";
  }
  text += "  </Collection>\n</VTKFile>\n";
  return text;
}

}  // namespace mrsim
