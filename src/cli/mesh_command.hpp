#pragma once
// `mrsim mesh INPUT|--shape NAME --tets 30,170,1900 -o PREFIX`: builds a hierarchy of
// independent tetrahedral meshes of one object (issue 3; docs/meshing.md). It runs as its own
// program, mrsim-mesh, beside mrsim (cli/mesher_handoff.hpp): gmsh and the ~100 libraries it
// loads (OpenCASCADE, FLTK, X11) then cost nothing to every other mrsim command.

namespace mrsim {

inline constexpr const char* kMeshDescription =
    "Build a hierarchy of tetrahedral meshes of one object, coarse to fine";

/// mrsim-mesh's command line: argv holds the options after `mrsim mesh`. Returns the exit code.
int run_mesh_cli(int argc, char** argv);

}  // namespace mrsim
