#include "physics/spectral_bound.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace mrsim {

namespace {

// y = M^-1/2 A M^-1/2 x, one gather per point (s = 1/√m, 0 where a point has no mass).
void apply(const PointAdjacency& adj, const std::vector<Mat3>& edge, const Eigen::VectorXd& s,
           const Eigen::VectorXd& x, Eigen::VectorXd& y) {
  const int n = adj.num_points();
  for (int i = 0; i < n; ++i) {
    const Vec3 ui = s[i] * x.segment<3>(3 * i);
    Vec3 yi = Vec3::Zero();
    for (int e = adj.nbr_start[i]; e < adj.nbr_start[i + 1]; ++e) {
      const int j = adj.nbr[e];
      yi.noalias() += edge[e] * (s[j] * x.segment<3>(3 * j) - ui);
    }
    y.segment<3>(3 * i) = s[i] * yi;
  }
}

// Largest Ritz value of the tridiagonal (alpha, beta) and its residual bound |β_k s_k|.
std::pair<double, double> top_ritz(const std::vector<double>& alpha,
                                   const std::vector<double>& beta) {
  const int k = static_cast<int>(alpha.size());
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(k, k);
  for (int i = 0; i < k; ++i) {
    T(i, i) = alpha[i];
    if (i + 1 < k) T(i, i + 1) = T(i + 1, i) = beta[i];
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(T);
  const int top = k - 1;  // eigenvalues ascending
  return {es.eigenvalues()[top], std::abs(beta[k - 1] * es.eigenvectors()(k - 1, top))};
}

}  // namespace

double largest_mass_scaled_eigenvalue(const PointAdjacency& adj, const std::vector<Mat3>& edge,
                                      const std::vector<double>& mass, double tolerance,
                                      int max_iterations) {
  const int n = adj.num_points(), dofs = 3 * n;
  if (n == 0 || edge.empty()) return 0;
  Eigen::VectorXd s(n);
  for (int i = 0; i < n; ++i) s[i] = mass[i] > 0 ? 1 / std::sqrt(mass[i]) : 0;
  // A fixed start vector with every component non-zero and no symmetry of the mesh.
  Eigen::VectorXd q(dofs), q_prev = Eigen::VectorXd::Zero(dofs), w(dofs);
  for (int k = 0; k < dofs; ++k) q[k] = 1.0 + 0.5 * std::sin(0.7 * k + 0.3 * (k % 7));
  q /= q.norm();
  std::vector<double> alpha, beta;
  double estimate = 0;
  for (int it = 0; it < std::min(max_iterations, dofs); ++it) {
    apply(adj, edge, s, q, w);
    if (it > 0) w -= beta.back() * q_prev;
    alpha.push_back(q.dot(w));
    w -= alpha.back() * q;
    beta.push_back(w.norm());
    const bool last = it + 1 == std::min(max_iterations, dofs);
    if (it % 5 == 4 || last || beta.back() == 0) {
      const auto [theta, residual] = top_ritz(alpha, beta);
      estimate = theta + residual;
      if (residual <= tolerance * std::abs(theta) || beta.back() == 0) break;
    }
    q_prev.swap(q);
    q = w / beta.back();
  }
  return std::max(estimate, 0.0);
}

SpectralScale spectral_scale(double eigenvalue, double star_max) {
  SpectralScale out{eigenvalue, star_max, 1.0};
  if (star_max > 0) out.scale = std::min(1.0, kSpectralMargin * eigenvalue / star_max);
  return out;
}

}  // namespace mrsim
