#pragma once
// `mrsim mesh ...` hands its arguments to the mrsim-mesh program installed beside mrsim
// (cli/mesh_command.hpp), which replaces the process: exit code, signals and output are its.

namespace mrsim {

/// The file name of the meshing program, looked for in mrsim's own folder.
inline constexpr const char* kMesherProgram = "mrsim-mesh";

/// Replaces this process by mrsim-mesh with argv[first..argc). Returns only when that fails,
/// having said why on stderr; the return value is then the exit code.
int hand_over_to_mesher(int argc, char** argv, int first);

}  // namespace mrsim
