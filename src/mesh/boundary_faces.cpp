#include "mesh/boundary_faces.hpp"

#include <algorithm>
#include <cstdint>

namespace mrsim {

namespace {

// The face opposite local vertex k of a positive tet, ordered so its normal points away from
// that vertex (outwards).
Face outward_face(const Tet& t, int k) {
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  return {t[kFaces[k][0]], t[kFaces[k][1]], t[kFaces[k][2]]};
}

// Sorts the entries by key and returns, in that order, the face of each key met once (a face
// of one tet only).
template <class Entry, class FaceOf>
std::vector<Face> single_faces(std::vector<Entry>& all, FaceOf face_of) {
  std::sort(all.begin(), all.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
  std::vector<Face> out;
  for (size_t i = 0; i < all.size();) {
    size_t j = i + 1;
    while (j < all.size() && all[j].key == all[i].key) ++j;
    if (j - i == 1) out.push_back(face_of(all[i]));
    i = j;
  }
  return out;
}

}  // namespace

std::vector<Face> boundary_faces_by_triples(const TetMesh& mesh) {
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
  return single_faces(all, [](const Entry& e) { return e.face; });
}

std::vector<Face> boundary_faces(const TetMesh& mesh) {
  // Each face once per tet, keyed by its sorted vertices; a key met once is a boundary face.
  // The three ids pack into one 64-bit key (21 bits each) whose order is the lexicographic
  // order of the sorted triples: the same faces in the same order as sorting the triples,
  // with cheaper comparisons and half the memory.
  constexpr int kBits = 21;
  if (mesh.points.size() >= (std::size_t{1} << kBits)) return boundary_faces_by_triples(mesh);
  struct Entry {
    std::uint64_t key;
    std::uint32_t slot;  // 4 × tet + local face
  };
  std::vector<Entry> all;
  all.reserve(4 * mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (int k = 0; k < 4; ++k) {
      Face key = outward_face(mesh.tets[t], k);
      std::sort(key.begin(), key.end());
      const auto id = [&](int a) { return static_cast<std::uint64_t>(key[a]); };
      all.push_back({(id(0) << (2 * kBits)) | (id(1) << kBits) | id(2),
                     static_cast<std::uint32_t>(4 * t + k)});
    }
  return single_faces(all, [&](const Entry& e) {
    return outward_face(mesh.tets[e.slot / 4], static_cast<int>(e.slot % 4));
  });
}

}  // namespace mrsim
