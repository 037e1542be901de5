#include "mesh/box_mesh.hpp"

#include <stdexcept>

namespace mrsim {

TetMesh make_box_mesh(const Vec3& min, const Vec3& max, int nx, int ny, int nz) {
  if (nx < 1 || ny < 1 || nz < 1) throw std::invalid_argument("make_box_mesh: cells must be >= 1");
  TetMesh mesh;
  auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  mesh.points.reserve(static_cast<size_t>((nx + 1) * (ny + 1) * (nz + 1)));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.points.emplace_back(min.x() + (max.x() - min.x()) * i / nx,
                                 min.y() + (max.y() - min.y()) * j / ny,
                                 min.z() + (max.z() - min.z()) * k / nz);
  // Kuhn split: the six tets around the main diagonal v0 -> v7 of every cell. Neighbouring
  // cells share face diagonals, so the mesh is conforming.
  static constexpr int kPaths[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
  mesh.tets.reserve(static_cast<size_t>(6 * nx * ny * nz));
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        int v[8];
        for (int c = 0; c < 8; ++c) v[c] = id(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
        for (const auto& p : kPaths) {
          Tet t{v[0], v[p[0]], v[p[1]], v[7]};
          if (signed_volume(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]],
                            mesh.points[t[3]]) < 0)
            std::swap(t[2], t[3]);
          mesh.tets.push_back(t);
        }
      }
  return mesh;
}

namespace {

// Node coordinates of one axis from relative cell widths scaled to [lo, hi].
std::vector<double> graded_nodes(double lo, double hi, const std::vector<double>& widths) {
  double total = 0;
  for (double w : widths) {
    if (!(w > 0)) throw std::invalid_argument("make_graded_box_mesh: widths must be > 0");
    total += w;
  }
  std::vector<double> x(widths.size() + 1, lo);
  for (size_t i = 0; i < widths.size(); ++i) x[i + 1] = x[i] + (hi - lo) * widths[i] / total;
  x.back() = hi;
  return x;
}

}  // namespace

TetMesh make_graded_box_mesh(const Vec3& min, const Vec3& max, const std::vector<double>& x_widths,
                             int ny, int nz) {
  return make_graded_box_mesh(min, max, x_widths, std::vector<double>(ny, 1.0),
                              std::vector<double>(nz, 1.0));
}

TetMesh make_graded_box_mesh(const Vec3& min, const Vec3& max, const std::vector<double>& x_widths,
                             const std::vector<double>& y_widths,
                             const std::vector<double>& z_widths) {
  const std::vector<double> x = graded_nodes(min.x(), max.x(), x_widths);
  const std::vector<double> y = graded_nodes(min.y(), max.y(), y_widths);
  const std::vector<double> z = graded_nodes(min.z(), max.z(), z_widths);
  const int nx = static_cast<int>(x_widths.size()), ny = static_cast<int>(y_widths.size()),
            nz = static_cast<int>(z_widths.size());
  // Point i + (nx+1)(j + (ny+1)k) of the uniform mesh: move it to the graded nodes.
  TetMesh mesh = make_box_mesh(min, max, nx, ny, nz);
  for (size_t p = 0; p < mesh.points.size(); ++p) {
    const size_t i = p % (nx + 1), j = (p / (nx + 1)) % (ny + 1), k = p / ((nx + 1) * (ny + 1));
    mesh.points[p] = Vec3(x[i], y[j], z[k]);
  }
  return mesh;
}

}  // namespace mrsim
