#pragma once
// The bundled level meshes of one object (scenarios/meshes/<name>_L<k>.vtu) with the points a
// predicate holds, as the calibration takes them (hierarchy and validation tests).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mesh/mesh_reader.hpp"

namespace mrsim::test_support {

struct BundledLevels {
  std::vector<TetMesh> meshes;
  std::vector<std::vector<std::uint8_t>> fixed;
  std::vector<const TetMesh*> pointers() const {
    std::vector<const TetMesh*> p;
    for (const TetMesh& m : meshes) p.push_back(&m);
    return p;
  }
};

inline BundledLevels bundled_levels(const std::string& name, int levels,
                                    const std::function<bool(const Vec3&)>& held) {
  BundledLevels b;
  for (int l = 0; l < levels; ++l) {
    b.meshes.push_back(read_tet_mesh(std::string(MRSIM_SOURCE_DIR) + "/scenarios/meshes/" + name +
                                         "_L" + std::to_string(l) + ".vtu",
                                     LengthUnit::Metre));
    std::vector<std::uint8_t> f;
    for (const Vec3& p : b.meshes.back().points) f.push_back(held(p) ? 1 : 0);
    b.fixed.push_back(f);
  }
  return b;
}

}  // namespace mrsim::test_support
