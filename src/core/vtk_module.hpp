#pragma once
// VTK is loaded when a run first reads a .vtu or writes VTK frames, not at start-up (issue 17):
// its libraries and their start-up cost about 10 ms of every process (`mrsim --version` 14.4 ms
// of CPU against 1.1 for a hello-world), as much as a quarter of a warm liver_probe set-up, and a
// run whose meshes come from the result cache (simulation/mesh_cache.hpp) with its frames off
// never needs them. mrsim's VTK readers and writers are built into libmrsim_vtk.so beside the
// executable, which exports the rest of mrsim to it; a program that links them in itself (the
// tests, mrsim-mesh) uses its own copy and loads nothing.
#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mrsim {

struct RawMesh;
class FrameSeriesWriter;
struct FrameBlock;
enum class FrameCompression;
using XmlAttributes = std::map<std::string, std::string>;

/// What mrsim calls in VTK's part of it; each entry is the function of that name
/// (mesh/vtu_reader.hpp, io/vtk_series_writer.hpp, compare/vtk_xml_index.hpp,
/// compare/vtm_frames.hpp).
struct VtkEntryPoints {
  // First, and checked before anything else is read: a library from another build (a partial
  // rebuild, a copy) could lay out this table or its types otherwise.
  std::size_t size;          // sizeof(VtkEntryPoints) where the library was built
  const char* git_revision;  // kGitRevision of the library's build
  RawMesh (*read_vtu)(const std::filesystem::path& path);
  std::unique_ptr<FrameSeriesWriter> (*series_writer)(const std::filesystem::path& out_dir,
                                                      FrameCompression compression);
  std::vector<XmlAttributes> (*read_dataset_entries)(const std::filesystem::path& file,
                                                     const std::string& type);
  std::vector<FrameBlock> (*read_vtm_frame)(const std::filesystem::path& vtm);
};

/// The entry points, loading libmrsim_vtk.so from the executable's folder on first use. Throws
/// RunError naming the library and the loader's reason when it cannot be loaded, or when it was
/// built from another revision than this mrsim.
const VtkEntryPoints& vtk_module();

/// RunError unless `e`, found in `library`, was built with this mrsim (same table, same
/// revision).
void check_vtk_entry_points(const VtkEntryPoints& e, const std::filesystem::path& library);

}  // namespace mrsim
