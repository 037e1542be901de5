#include "mesh/face_buckets.hpp"

#include <algorithm>

namespace mrsim {

namespace {

std::array<int, 3> sorted(std::array<int, 3> f) {
  if (f[0] > f[1]) std::swap(f[0], f[1]);
  if (f[1] > f[2]) std::swap(f[1], f[2]);
  if (f[0] > f[1]) std::swap(f[0], f[1]);
  return f;
}

}  // namespace

std::array<int, 3> outward_face(const Tet& t, int k) {
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  return {t[kFaces[k][0]], t[kFaces[k][1]], t[kFaces[k][2]]};
}

FaceBuckets::FaceBuckets(const TetMesh& mesh) {
  const std::size_t np = mesh.points.size(), nt = mesh.tets.size();
  start.assign(np + 1, 0);
  for (const Tet& t : mesh.tets)
    for (int k = 0; k < 4; ++k) ++start[sorted(outward_face(t, k))[0] + 1];
  for (std::size_t p = 0; p < np; ++p) start[p + 1] += start[p];
  entries.resize(start[np]);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 4; ++k) {
      const auto key = sorted(outward_face(mesh.tets[t], k));
      entries[fill[key[0]]++] = {
          (static_cast<std::uint64_t>(key[1]) << 32) | static_cast<std::uint32_t>(key[2]),
          static_cast<std::uint32_t>(4 * t + k)};
    }
  for (std::size_t p = 0; p < np; ++p)
    std::sort(entries.begin() + start[p], entries.begin() + start[p + 1],
              [](const Entry& a, const Entry& b) { return a.rest < b.rest; });
}

}  // namespace mrsim
