#pragma once
// The bundled liver's four levels (scenarios/meshes/liver_L0..3.vtu, as liver_probe loads
// them), read once per benchmark process.
#include <string>
#include <vector>

#include "mesh/mesh_reader.hpp"

namespace mrsim::bench {

inline const std::vector<TetMesh>& bundled_liver_levels() {
  static const std::vector<TetMesh> meshes = [] {
    std::vector<TetMesh> m;
    for (int l = 0; l < 4; ++l)
      m.push_back(read_tet_mesh(std::string(MRSIM_SOURCE_DIR) + "/scenarios/meshes/liver_L" +
                                    std::to_string(l) + ".vtu",
                                LengthUnit::Metre));
    return m;
  }();
  return meshes;
}

}  // namespace mrsim::bench
