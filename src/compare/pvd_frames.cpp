#include "compare/pvd_frames.hpp"

#include <charconv>
#include <string>

#include "compare/vtk_xml_index.hpp"
#include "core/error.hpp"
#include "core/vtk_module.hpp"

namespace mrsim {
namespace {

double parse_time(const std::string& text, const std::filesystem::path& pvd) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) {
    throw InputError(pvd.string() + ": timestep '" + text + "' is not a number");
  }
  return value;
}

}  // namespace

std::vector<PvdFrame> read_pvd_frames(const std::filesystem::path& pvd) {
  std::vector<PvdFrame> frames;
  for (const XmlAttributes& entry : vtk_module().read_dataset_entries(pvd, "Collection")) {
    const double time = parse_time(required_attribute(entry, "timestep", pvd), pvd);
    frames.push_back({time, pvd.parent_path() / required_attribute(entry, "file", pvd)});
  }
  return frames;
}

long long frame_number(const std::filesystem::path& vtm, long long fallback) {
  const std::string stem = vtm.stem().string();
  const std::size_t underscore = stem.rfind('_');
  if (underscore == std::string::npos) return fallback;
  long long number = 0;
  const char* begin = stem.data() + underscore + 1;
  const char* end = stem.data() + stem.size();
  const auto [stop, ec] = std::from_chars(begin, end, number);
  return ec == std::errc() && stop == end && begin != end ? number : fallback;
}

// Here, not beside read_dataset_entries: that one is in VTK's library (core/vtk_module.hpp),
// this one is called on both sides of it.
const std::string& required_attribute(const XmlAttributes& entry, const std::string& name,
                                      const std::filesystem::path& file) {
  const auto it = entry.find(name);
  if (it == entry.end())
    throw InputError(file.string() + ": a DataSet element has no '" + name + "' attribute");
  return it->second;
}

}  // namespace mrsim
