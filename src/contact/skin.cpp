#include "contact/skin.hpp"

#include "mesh/boundary_faces.hpp"

namespace mrsim {

namespace {

std::vector<double> vertex_areas(const Skin& s) {
  std::vector<double> area(s.rest.size(), 0.0);
  for (const auto& t : s.triangles) {
    const double a =
        0.5 * (s.rest[t[1]] - s.rest[t[0]]).cross(s.rest[t[2]] - s.rest[t[0]]).norm();
    for (int v : t) area[v] += a / 3.0;
  }
  return area;
}

std::vector<double> mean_edges(const Skin& s) {
  std::vector<double> sum(s.rest.size(), 0.0), count(s.rest.size(), 0.0);
  for (const auto& t : s.triangles)
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      const double len = (s.rest[a] - s.rest[b]).norm();
      sum[a] += len;
      sum[b] += len;
      count[a] += 1;
      count[b] += 1;
    }
  for (std::size_t v = 0; v < sum.size(); ++v) sum[v] = count[v] > 0 ? sum[v] / count[v] : 0.0;
  return sum;
}

}  // namespace

Skin boundary_skin(const TetMesh& mesh) {
  const std::vector<Face> faces = boundary_faces(mesh);
  std::vector<int> index(mesh.points.size(), -1);
  for (const Face& f : faces)
    for (int v : f) index[v] = 0;
  Skin s;
  for (std::size_t p = 0; p < index.size(); ++p)
    if (index[p] == 0) {
      index[p] = static_cast<int>(s.rest.size());
      s.rest.push_back(mesh.points[p]);
      s.point.push_back(static_cast<int>(p));
    }
  for (const Face& f : faces) s.triangles.push_back({index[f[0]], index[f[1]], index[f[2]]});
  s.area = vertex_areas(s);
  s.edge = mean_edges(s);
  return s;
}

Skin surface_skin(std::vector<Vec3> points, std::vector<std::array<int, 3>> triangles) {
  Skin s{std::move(points), std::move(triangles), {}, {}, {}};
  s.area = vertex_areas(s);
  s.edge = mean_edges(s);
  return s;
}

}  // namespace mrsim
