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

Face sorted(Face f) {
  if (f[0] > f[1]) std::swap(f[0], f[1]);
  if (f[1] > f[2]) std::swap(f[1], f[2]);
  if (f[0] > f[1]) std::swap(f[0], f[1]);
  return f;
}

// One face of one tet, in the bucket of its smallest vertex: its two other vertices (sorted,
// the larger in the low bits) and where it comes from.
struct Entry {
  std::uint64_t rest;
  std::uint32_t slot;  // 4 × tet + local face
};

}  // namespace

std::vector<Face> boundary_faces(const TetMesh& mesh) {
  // Each face once per tet, keyed by its sorted vertices; a key met once is a boundary face.
  // The faces are bucketed by their smallest vertex (a counting sort: every bucket holds a few
  // dozen faces) and each bucket is sorted by the two others: the keys in lexicographic order,
  // as a sort of all 4T triples would give, in linear time rather than O(T log T).
  const std::size_t np = mesh.points.size(), nt = mesh.tets.size();
  std::vector<std::uint32_t> start(np + 1, 0);
  for (const Tet& t : mesh.tets)
    for (int k = 0; k < 4; ++k) ++start[sorted(outward_face(t, k))[0] + 1];
  for (std::size_t p = 0; p < np; ++p) start[p + 1] += start[p];
  std::vector<Entry> all(start[np]);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 4; ++k) {
      const Face key = sorted(outward_face(mesh.tets[t], k));
      all[fill[key[0]]++] = {(static_cast<std::uint64_t>(key[1]) << 32) | static_cast<std::uint32_t>(key[2]),
                             static_cast<std::uint32_t>(4 * t + k)};
    }
  std::vector<Face> out;
  for (std::size_t p = 0; p < np; ++p) {
    const auto first = all.begin() + start[p], last = all.begin() + start[p + 1];
    // Equal keys need no particular order: a key met more than once yields no face.
    std::sort(first, last, [](const Entry& a, const Entry& b) { return a.rest < b.rest; });
    for (auto i = first; i != last;) {
      auto j = i + 1;
      while (j != last && j->rest == i->rest) ++j;
      if (j - i == 1) out.push_back(outward_face(mesh.tets[i->slot / 4], static_cast<int>(i->slot % 4)));
      i = j;
    }
  }
  return out;
}

}  // namespace mrsim
