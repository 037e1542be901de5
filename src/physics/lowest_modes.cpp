#include "physics/lowest_modes.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/portable_math.hpp"

namespace mrsim {

namespace {

// A shift well below the lowest eigenvalue: a small fraction of the mean K_ii/m_i, negative.
double shift_below(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& mass) {
  return -1e-4 * (K.diagonal().array() / mass.array()).mean();
}

}  // namespace

Modes lowest_modes(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& mass, int count,
                   double tolerance) {
  const int n = static_cast<int>(mass.size());
  if (std::min(count, n) <= 0) return {};
  const double sigma = shift_below(K, mass);
  Eigen::SparseMatrix<double> A = K;
  for (int i = 0; i < n; ++i) A.coeffRef(i, i) -= sigma * mass[i];
  const SparseLdlt solver(A);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("lowest_modes: K - sigma M is not positive definite");
  return lowest_modes(solver, sigma, mass, count, tolerance);
}

Modes lowest_modes(const SparseLdlt& solver, double sigma, const Eigen::VectorXd& mass, int count,
                   double tolerance) {
  const int n = static_cast<int>(mass.size());
  count = std::min(count, n);
  Modes out;
  if (count <= 0) return out;
  int steps = std::min(n, std::max(2 * count + 20, 40));
  for (;;) {
    // Lanczos on Op = A⁻¹M, M-orthonormal basis Q; deterministic start vector.
    Eigen::MatrixXd Q(n, steps);
    Eigen::VectorXd alpha(steps), beta(steps);
    Eigen::VectorXd q(n);
    for (int i = 0; i < n; ++i) q[i] = 1.0 + 0.5 * portable::sin(1.7 * i + 0.3);
    q /= std::sqrt(q.dot(mass.cwiseProduct(q)));
    int m = 0;
    for (; m < steps; ++m) {
      Q.col(m) = q;
      Eigen::VectorXd w = solver.solve(mass.cwiseProduct(q));
      alpha[m] = w.dot(mass.cwiseProduct(q));
      for (int pass = 0; pass < 2; ++pass)  // full reorthogonalisation, twice
        for (int k = 0; k <= m; ++k) w -= Q.col(k) * Q.col(k).dot(mass.cwiseProduct(w));
      beta[m] = std::sqrt(std::max(0.0, w.dot(mass.cwiseProduct(w))));
      if (beta[m] <= 1e-14 * std::abs(alpha[m]) || m + 1 == steps) {
        ++m;
        break;
      }
      q = w / beta[m];
    }
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(m, m);
    for (int k = 0; k < m; ++k) {
      T(k, k) = alpha[k];
      if (k + 1 < m) T(k, k + 1) = T(k + 1, k) = beta[k];
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(T);
    const int have = std::min(count, m);
    // θ = 1/(ω² − σ): the largest θ are the lowest modes; residual β_m |s_m|.
    bool converged = true;
    for (int k = 0; k < have; ++k) {
      const int col = m - 1 - k;
      const double theta = es.eigenvalues()[col];
      if (beta[m - 1] * std::abs(es.eigenvectors()(m - 1, col)) > tolerance * std::abs(theta))
        converged = false;
    }
    if (converged || m < steps || steps >= n) {
      out.omega2.resize(have);
      out.shapes.resize(n, have);
      for (int k = 0; k < have; ++k) {
        const int col = m - 1 - k;
        out.omega2[k] = sigma + 1.0 / es.eigenvalues()[col];
        out.shapes.col(k) = Q.leftCols(m) * es.eigenvectors().col(col);
      }
      return out;
    }
    steps = std::min(n, 2 * steps);
  }
}

}  // namespace mrsim
