#include "physics/component_stiffness.hpp"

#include "physics/edge_operators.hpp"

namespace mrsim {

SparseMatrix ComponentStiffness::combined(const std::array<double, 7>& scales) const {
  SparseMatrix k = scales[0] * parts[0];
  for (int j = 1; j < 7; ++j) k += scales[j] * parts[j];
  return k;
}

ComponentStiffness component_stiffness(const TetGeometry& geo, int n, const MaterialLaw& law,
                                       const std::vector<std::uint8_t>& fixed) {
  ComponentStiffness out;
  out.dof_of_point.assign(n, -1);
  int dofs = 0;
  for (int i = 0; i < n; ++i)
    if (fixed.empty() || !fixed[i]) {
      out.dof_of_point[i] = dofs;
      dofs += 3;
    }
  out.mass = Eigen::VectorXd::Zero(dofs);
  for (size_t t = 0; t < geo.tets.size(); ++t)
    for (int v : geo.tets[t])
      if (out.dof_of_point[v] >= 0)
        out.mass.segment<3>(out.dof_of_point[v]).array() += law.density * geo.volume[t] / 4;
  for (int j = 0; j < 7; ++j) {
    // The tensor with factor 1 on component j and 0 on the others.
    std::array<double, 7> unit{};
    unit[j] = 1;
    const StiffnessScales only = StiffnessScales::from_components(unit);
    const double lam = law.lambda * only.lambda;
    double mu[3][3];
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) mu[p][q] = law.mu * only.mu[3 * p + q];
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(geo.tets.size() * 144);
    for (size_t t = 0; t < geo.tets.size(); ++t)
      for (int a = 0; a < 4; ++a) {
        const int da = out.dof_of_point[geo.tets[t][a]];
        if (da < 0) continue;
        for (int b = 0; b < 4; ++b) {
          const int db = out.dof_of_point[geo.tets[t][b]];
          if (db < 0) continue;
          // Every entry is stored, zeros included, so that the seven parts share one pattern.
          const Mat3 k = orthotropic_block(geo.grad[t][a], geo.grad[t][b], geo.volume[t], lam, mu);
          for (int p = 0; p < 3; ++p)
            for (int r = 0; r < 3; ++r) entries.emplace_back(da + p, db + r, k(p, r));
        }
      }
    out.parts[j].resize(dofs, dofs);
    out.parts[j].setFromTriplets(entries.begin(), entries.end());
  }
  return out;
}

}  // namespace mrsim
