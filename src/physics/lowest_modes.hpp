#pragma once
// The lowest vibration modes of K x = ω² M x (M lumped, diagonal) by shift-invert Lanczos with
// full reorthogonalisation: Lanczos on (K − σM)⁻¹M in the M inner product, σ < 0 below the
// spectrum so that the factorised matrix is positive definite even for a free body (whose six
// rigid modes then come first, at ω² ≈ 0). Set-up only (calibration, tests).
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

namespace mrsim {

struct Modes {
  Eigen::VectorXd omega2;  // ascending
  Eigen::MatrixXd shapes;  // M-orthonormal columns
};

using SparseLdlt = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;

/// The `count` lowest modes, each to a relative residual below `tolerance` (more Lanczos steps
/// are taken until they are). Throws std::runtime_error when the factorisation fails.
Modes lowest_modes(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& mass, int count,
                   double tolerance = 1e-8);

/// The same with K − σM already factorised (σ ≤ 0 below the spectrum; σ = 0 for a held body,
/// whose factorised K also gives its static solves).
Modes lowest_modes(const SparseLdlt& shifted, double sigma, const Eigen::VectorXd& mass, int count,
                   double tolerance = 1e-8);

}  // namespace mrsim
