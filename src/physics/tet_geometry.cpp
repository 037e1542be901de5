#include "physics/tet_geometry.hpp"

#include <stdexcept>
#include <string>

namespace mrsim {

TetGeometry build_tet_geometry(const TetMesh& mesh, const MaterialLaw* law) {
  TetGeometry geo;
  const size_t n = mesh.tets.size();
  geo.tets = mesh.tets;
  geo.volume.resize(n);
  geo.grad.resize(n);
  for (size_t t = 0; t < n; ++t) {
    const Tet& v = mesh.tets[t];
    const Vec3& x0 = mesh.points[v[0]];
    Mat3 D;
    D.col(0) = mesh.points[v[1]] - x0;
    D.col(1) = mesh.points[v[2]] - x0;
    D.col(2) = mesh.points[v[3]] - x0;
    const double det = D.determinant();
    if (!(det > 0))
      throw std::invalid_argument("build_tet_geometry: tet " + std::to_string(t) +
                                  " is not positively oriented");
    geo.volume[t] = det / 6.0;
    // Rows of D^{-1} are the gradients of N_1..N_3 (N_a(X) = e_a · D^{-1}(X - X0)).
    const Mat3 Dinv = D.inverse();
    for (int a = 1; a < 4; ++a) geo.grad[t][a] = Dinv.row(a - 1).transpose();
    geo.grad[t][0] = -(geo.grad[t][1] + geo.grad[t][2] + geo.grad[t][3]);
  }
  if (law && law->tet_tensors) {
    const TetTensors& q = *law->tet_tensors;
    if (q.size() != n)
      throw std::invalid_argument("build_tet_geometry: " + std::to_string(q.size()) +
                                  " tet tensors for " + std::to_string(n) + " tets");
    geo.scales.reserve(n);
    for (size_t t = 0; t < n; ++t) geo.scales.push_back(law->scales.times(q[t]));
  }
  return geo;
}

}  // namespace mrsim
