#pragma once
// Test helpers for the stable step: materials, jittered boxes and the dense truth, the largest
// eigenvalue of M^-1/2 K M^-1/2 of a whole level (small meshes only).
#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "mesh/box_mesh.hpp"
#include "physics/level_model.hpp"

namespace mrsim::test_support {

inline MaterialLaw law_with(double lambda, double mu, double phi = 0, double psi = 0) {
  MaterialLaw law;
  law.strain = StrainMeasure::Cauchy;
  law.lambda = lambda;
  law.mu = mu;
  law.phi = phi;
  law.psi = psi;
  law.density = 1000;
  return law;
}

inline TetMesh jittered_box(int nx, int ny, int nz, double jitter, unsigned seed) {
  TetMesh m = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.04, 0.03), nx, ny, nz);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-jitter, jitter);
  const Vec3 h(0.1 / nx, 0.04 / ny, 0.03 / nz);
  for (Vec3& p : m.points)
    if (p.x() > 1e-9 && p.x() < 0.1 - 1e-9 && p.y() > 1e-9 && p.y() < 0.04 - 1e-9 && p.z() > 1e-9 &&
        p.z() < 0.03 - 1e-9)
      p += Vec3(d(rng) * h.x(), d(rng) * h.y(), d(rng) * h.z());
  return m;
}

// M^-1/2 (coefficient × A) M^-1/2 of a whole free level, dense, from its CSR edge blocks: A_ij
// off the diagonal and own × Σ_j A_ij on it (own = -1: A itself; +1: A − 2 blockdiag A).
inline Eigen::MatrixXd dense_operator(const LevelModel& m, const std::vector<Mat3>& blocks,
                                      double own = -1, double coefficient = 1) {
  const int n = m.num_points();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < n; ++i)
    for (int e = m.adj.nbr_start[i]; e < m.adj.nbr_start[i + 1]; ++e) {
      const int j = m.adj.nbr[e];
      A.block<3, 3>(3 * i, 3 * j) += coefficient * blocks[e];
      A.block<3, 3>(3 * i, 3 * i) += (own * coefficient) * blocks[e];
    }
  for (int i = 0; i < 3 * n; ++i)
    for (int j = 0; j < 3 * n; ++j) A(i, j) /= std::sqrt(m.mass[i / 3] * m.mass[j / 3]);
  return A;
}

// The rows and columns of the points not held (`held` per point, 1 = held).
inline Eigen::MatrixXd free_block(const Eigen::MatrixXd& A, const std::vector<std::uint8_t>& held) {
  std::vector<int> dofs;
  for (int i = 0; i < static_cast<int>(held.size()); ++i)
    if (!held[i])
      for (int d = 0; d < 3; ++d) dofs.push_back(3 * i + d);
  Eigen::MatrixXd F(dofs.size(), dofs.size());
  for (size_t a = 0; a < dofs.size(); ++a)
    for (size_t b = 0; b < dofs.size(); ++b) F(a, b) = A(dofs[a], dofs[b]);
  return F;
}

inline double largest_eigenvalue(const Eigen::MatrixXd& A) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A, Eigen::EigenvaluesOnly)
      .eigenvalues()
      .maxCoeff();
}

// ω_max² of the free (unsupported) level: the largest eigenvalue of M^-1/2 K M^-1/2 (of D with
// `damping`; of K − 2 blockdiag K with `filtered`, what the semi-implicit filter leaves).
inline double omega_max_squared(const LevelModel& m, bool damping = false, bool filtered = false) {
  return largest_eigenvalue(dense_operator(m, damping ? m.D : m.K, filtered ? 1.0 : -1.0));
}

}  // namespace mrsim::test_support
