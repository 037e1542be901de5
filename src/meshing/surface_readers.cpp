#include "meshing/surface_readers.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace mrsim {
namespace {

std::string read_bytes(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(path.string() + ": no such file");
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in && !in.eof()) throw InputError(path.string() + ": cannot read the file");
  return std::move(bytes).str();
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

void add_polygon(SurfaceMesh& surface, const std::vector<int>& corners, int face_number) {
  // A fan keeps every corner; a zero-area triangle it may produce (a polygon with collinear
  // corners) is reported by the checks rather than silently dropped.
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
    surface.triangles.push_back({corners[0], corners[k], corners[k + 1]});
    surface.face_of.push_back(face_number);
  }
}

SurfaceMesh read_surface(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  using Reader = SurfaceMesh (*)(const std::string&, const std::filesystem::path&);
  Reader reader = nullptr;
  if (ext == ".stl") reader = read_stl;
  else if (ext == ".obj") reader = read_obj;
  else if (ext == ".off") reader = read_off;
  else if (ext == ".ply") reader = read_ply;
  else {
    throw InputError(path.string() + ": unknown surface format '" + ext +
                     "' (expected .stl, .obj, .off or .ply)");
  }
  SurfaceMesh surface = reader(read_bytes(path), path);
  if (surface.triangles.empty()) throw InputError(path.string() + ": the surface has no faces");
  return surface;
}

}  // namespace mrsim
