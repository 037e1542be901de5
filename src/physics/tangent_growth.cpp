#include "physics/tangent_growth.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>

namespace mrsim {

double tangent_growth(const Mat3& grad_u, const MaterialLaw& law) {
  const Mat3 F = Mat3::Identity() + grad_u;
  const Mat3 E = 0.5 * (F.transpose() * F - Mat3::Identity());
  Eigen::SelfAdjointEigenSolver<Mat3> es;
  es.computeDirect(E, Eigen::EigenvaluesOnly);
  const double e_max = es.eigenvalues()(2);
  const double lambda = law.bound_lambda(), mu = law.bound_mu();
  if (!(lambda + 2 * mu > 0)) return std::max(0.0, 2 * e_max);  // no stress: the material part
  const double stress = lambda * E.trace() + 2 * mu * e_max;
  const double growth = 2 * e_max + std::max(0.0, stress) / (lambda + 2 * mu);
  return std::max(0.0, growth);
}

double largest_tangent_growth(const TetGeometry& geo, std::span<const int> tets,
                              const std::vector<Vec3>& u, const MaterialLaw& law) {
  double top = 0;
  for (const int t : tets)
    top = std::max(top, tangent_growth(tet_gradient(geo.grad[t], geo.tets[t], u.data()), law));
  return top;
}

}  // namespace mrsim
