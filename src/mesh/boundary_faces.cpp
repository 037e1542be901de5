#include "mesh/boundary_faces.hpp"

#include <algorithm>

namespace mrsim {

namespace {

// The face opposite local vertex k of a positive tet, ordered so its normal points away from
// that vertex (outwards).
Face outward_face(const Tet& t, int k) {
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  return {t[kFaces[k][0]], t[kFaces[k][1]], t[kFaces[k][2]]};
}

}  // namespace

std::vector<Face> boundary_faces(const TetMesh& mesh) {
  struct Entry {
    Face key;   // sorted vertices
    Face face;  // oriented
  };
  std::vector<Entry> all;
  all.reserve(4 * mesh.tets.size());
  for (const Tet& t : mesh.tets)
    for (int k = 0; k < 4; ++k) {
      Entry e{outward_face(t, k), outward_face(t, k)};
      std::sort(e.key.begin(), e.key.end());
      all.push_back(e);
    }
  std::sort(all.begin(), all.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
  std::vector<Face> out;
  for (size_t i = 0; i < all.size();) {
    size_t j = i + 1;
    while (j < all.size() && all[j].key == all[i].key) ++j;
    if (j - i == 1) out.push_back(all[i].face);
    i = j;
  }
  return out;
}

}  // namespace mrsim
