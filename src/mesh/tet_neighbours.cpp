#include "mesh/tet_neighbours.hpp"

#include "mesh/face_buckets.hpp"

namespace mrsim {

std::vector<std::array<int, 4>> tet_neighbours(const TetMesh& mesh) {
  std::vector<std::array<int, 4>> out(mesh.tets.size(), {-1, -1, -1, -1});
  using Entry = FaceBuckets::Entry;
  FaceBuckets(mesh).for_each_face([&](const Entry* first, const Entry* last) {
    if (last - first != 2) return;
    const std::uint32_t a = first->slot, b = (first + 1)->slot;
    out[a / 4][a % 4] = static_cast<int>(b / 4);
    out[b / 4][b % 4] = static_cast<int>(a / 4);
  });
  return out;
}

}  // namespace mrsim
