#include "physics/component_stiffness.hpp"

#include "physics/edge_operators.hpp"

namespace mrsim {

namespace {

// The tensor with factor 1 on component j and 0 on the others.
OrthotropicTensor component_tensor(int j, double lambda, double mu) {
  std::array<double, 7> unit{};
  unit[j] = 1;
  return orthotropic_tensor(lambda, mu, StiffnessScales::from_components(unit));
}

// Σ_t V_t Bᵀ C_t B over the free DoFs of `cs`, C_t = tensor(t). Every entry is stored, zeros
// included, so that matrices of one level share one pattern.
template <class TensorOf>
SparseMatrix assemble(const ComponentStiffness& cs, TensorOf tensor) {
  const TetGeometry& geo = cs.geo;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(geo.tets.size() * 144);
  for (int t = 0; t < cs.num_tets(); ++t) {
    const OrthotropicTensor c = tensor(t);
    for (int a = 0; a < 4; ++a) {
      const int da = cs.dof_of_point[geo.tets[t][a]];
      if (da < 0) continue;
      for (int b = 0; b < 4; ++b) {
        const int db = cs.dof_of_point[geo.tets[t][b]];
        if (db < 0) continue;
        const Mat3 k =
            orthotropic_block(geo.grad[t][a], geo.grad[t][b], geo.volume[t], c.lambda, c.mu);
        for (int p = 0; p < 3; ++p)
          for (int r = 0; r < 3; ++r) entries.emplace_back(da + p, db + r, k(p, r));
      }
    }
  }
  SparseMatrix out(cs.free_dofs(), cs.free_dofs());
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

// The free-DoF field `x` of tet t's vertices (fixed points: zero) as its strain ε = sym(∇x).
Mat3 tet_strain(const ComponentStiffness& cs, int t, const Eigen::VectorXd& x) {
  Mat3 G = Mat3::Zero();
  for (int a = 0; a < 4; ++a) {
    const int d = cs.dof_of_point[cs.geo.tets[t][a]];
    if (d >= 0) G.noalias() += x.segment<3>(d) * cs.geo.grad[t][a].transpose();
  }
  return 0.5 * (G + G.transpose());
}

}  // namespace

SparseMatrix ComponentStiffness::combined(const std::array<double, 7>& scales) const {
  SparseMatrix k = scales[0] * parts[0];
  for (int j = 1; j < 7; ++j) k += scales[j] * parts[j];
  return k;
}

SparseMatrix ComponentStiffness::combined(const std::array<double, 7>& scales,
                                          const TetTensors& tets) const {
  // One tensor per tet: the orthotropic blocks of its K_tj summed with the factors.
  const StiffnessScales level = StiffnessScales::from_components(scales);
  return assemble(*this, [&](int t) { return orthotropic_tensor(lambda, mu, level.times(tets[t])); });
}

std::vector<ComponentValues> ComponentStiffness::tet_terms(const Eigen::VectorXd& a,
                                                           const Eigen::VectorXd& b) const {
  // aᵀ K_tj b = V (λ_j tr ε_a tr ε_b + 2 Σ_pq μ_j[p][q] ε_a,pq ε_b,pq): the orthotropic block's
  // bilinear form written with the strains (docs/hierarchy.md "Calibrated levels").
  std::vector<ComponentValues> out(geo.tets.size());
  for (int t = 0; t < num_tets(); ++t) {
    const Mat3 ea = tet_strain(*this, t, a), eb = tet_strain(*this, t, b);
    const double V = geo.volume[t];
    out[t][0] = V * lambda * ea.trace() * eb.trace();
    for (int d = 0; d < 3; ++d) out[t][1 + d] = V * 2 * mu * ea(d, d) * eb(d, d);
    // yz, xz, xy: the pair (p, q) and (q, p), each 2 μ ε_pq.
    out[t][4] = V * 4 * mu * ea(1, 2) * eb(1, 2);
    out[t][5] = V * 4 * mu * ea(0, 2) * eb(0, 2);
    out[t][6] = V * 4 * mu * ea(0, 1) * eb(0, 1);
  }
  return out;
}

ComponentStiffness component_stiffness(const TetGeometry& geo, int n, const MaterialLaw& law,
                                       const std::vector<std::uint8_t>& fixed) {
  ComponentStiffness out;
  out.geo = geo;
  out.lambda = law.lambda;
  out.mu = law.mu;
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
    const OrthotropicTensor c = component_tensor(j, law.lambda, law.mu);
    out.parts[j] = assemble(out, [&c](int) { return c; });
  }
  return out;
}

}  // namespace mrsim
