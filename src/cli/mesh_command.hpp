#pragma once
// `mrsim mesh INPUT|--shape NAME --tets 30,170,1900 -o PREFIX`: builds a hierarchy of
// independent tetrahedral meshes of one object (issue 3; docs/meshing.md).
#include <functional>

#include <CLI/CLI.hpp>

namespace mrsim {

struct MeshCommand {
  CLI::App* command = nullptr;  // true (parsed) when the user chose `mesh`
  std::function<int()> run;     // runs it; InputError and RunError propagate to the caller
};

/// Registers the subcommand and its options on `app`.
MeshCommand add_mesh_command(CLI::App& app);

}  // namespace mrsim
