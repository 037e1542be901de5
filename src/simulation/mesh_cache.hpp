#pragma once
// A level's VTK XML mesh kept between runs in binary (issue 17): VTK's reader, its pipeline and
// LZ4 took 5 ms of a warm liver_probe set-up of 43 for four small files, more than the rest of
// reading them. One file per mesh under meshes/ in the result cache
// (simulation/result_cache.hpp), keyed by the file's path and bytes, the length unit and this build,
// so an edited mesh or another mrsim reads the file again; what it holds is checked (indices in range,
// finite points, positive tets) before use. The report it gives back is the reading's own: the
// warnings of the first read are said again on every run, as they were.
#include <filesystem>

#include "mesh/mesh_reader.hpp"

namespace mrsim {

/// read_tet_mesh(path, unit, report), from the result cache when this build read these very
/// bytes in this unit before (`reused` says which). Only .vtu files are kept: the other formats
/// are read by mrsim's own parsers, as fast as a cached copy. Errors are read_tet_mesh's.
TetMesh read_level_mesh(const std::filesystem::path& path, LengthUnit unit,
                        MeshReadReport* report = nullptr, bool* reused = nullptr);

}  // namespace mrsim
