#include "mesh/boundary_faces.hpp"

#include "mesh/face_buckets.hpp"

namespace mrsim {

std::vector<Face> boundary_faces(const TetMesh& mesh) {
  // A vertex triple met once is a boundary face, taken as its tet orients it.
  std::vector<Face> out;
  using Entry = FaceBuckets::Entry;
  FaceBuckets(mesh).for_each_face([&](const Entry* first, const Entry* last) {
    if (last - first == 1)
      out.push_back(outward_face(mesh.tets[first->slot / 4], static_cast<int>(first->slot % 4)));
  });
  return out;
}

}  // namespace mrsim
