// The eigenvalues of a symmetric 3x3 matrix (core/symmetric_eigenvalues.hpp) against Eigen's
// iterative solver: random matrices, known spectra under rotation, repeated eigenvalues, extreme
// scales, and NaN propagating.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <utility>

#include "core/symmetric_eigenvalues.hpp"

using namespace mrsim;

namespace {

Mat3 random_symmetric(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> pick(-1.0, 1.0);
  Mat3 a;
  for (int i = 0; i < 9; ++i) a.data()[i] = scale * pick(rng);
  return 0.5 * (a + a.transpose());
}

Mat3 rotated(const Vec3& spectrum, const Eigen::Quaterniond& q) {
  const Mat3 r = q.normalized().toRotationMatrix();
  return r * spectrum.asDiagonal() * r.transpose();
}

}  // namespace

TEST(SymmetricEigenvalues, MatchTheIterativeSolverOnRandomMatrices) {
  std::mt19937_64 rng(3);
  for (int k = 0; k < 20000; ++k) {
    const Mat3 a = random_symmetric(rng, 1.0);
    const Vec3 mine = symmetric_eigenvalues(a);
    const Vec3 ref = Eigen::SelfAdjointEigenSolver<Mat3>(a, Eigen::EigenvaluesOnly).eigenvalues();
    ASSERT_LE((mine - ref).cwiseAbs().maxCoeff(), 1e-13 * a.norm()) << a;
    ASSERT_LE(mine(0), mine(1));
    ASSERT_LE(mine(1), mine(2));
  }
}

// A double root (or two roots both tiny at the matrix's scale) moves by about sqrt(eps) of the
// scale under rounding of the cubic's coefficients: that is the trigonometric method's own
// accuracy there (Eigen's computeDirect, which this replaces, does no better), and the bounds
// built on it have far more margin.
TEST(SymmetricEigenvalues, RecoverAKnownSpectrumUnderAnyRotation) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g;
  for (const auto& [spectrum, tolerance] :
       {std::pair{Vec3(-2.0, 0.5, 3.0), 1e-13}, {Vec3(1.0, 1.0, 4.0), 1e-7},
        {Vec3(-1.0, 2.0, 2.0), 1e-7}, {Vec3(1e-9, 1.0, 1e9), 1e-7}}) {  // last: 0, 0 at its scale
    double worst = 0, worst_direct = 0;
    for (int k = 0; k < 200; ++k) {
      const Mat3 a = rotated(spectrum, {g(rng), g(rng), g(rng), g(rng)});
      Eigen::SelfAdjointEigenSolver<Mat3> direct;
      direct.computeDirect(a, Eigen::EigenvaluesOnly);
      worst = std::max(worst, (symmetric_eigenvalues(a) - spectrum).cwiseAbs().maxCoeff());
      worst_direct = std::max(worst_direct, (direct.eigenvalues() - spectrum).cwiseAbs().maxCoeff());
    }
    const double scale = spectrum.cwiseAbs().maxCoeff();
    EXPECT_LE(worst, tolerance * scale) << spectrum.transpose();
    EXPECT_LE(worst, 4 * worst_direct + 1e-14 * scale) << spectrum.transpose();
  }
}

TEST(SymmetricEigenvalues, DiagonalAndScalarMatricesAreExact) {
  EXPECT_EQ(symmetric_eigenvalues(Mat3::Identity() * 2.5), Vec3::Constant(2.5));
  EXPECT_EQ(symmetric_eigenvalues(Mat3::Zero()), Vec3::Zero());
  const Vec3 d = symmetric_eigenvalues(Vec3(3.0, -1.0, 0.0).asDiagonal());
  EXPECT_NEAR(d(0), -1.0, 1e-15);
  EXPECT_NEAR(d(1), 0.0, 1e-15);
  EXPECT_NEAR(d(2), 3.0, 1e-15);
}

TEST(SymmetricEigenvalues, ExtremeScalesNeitherOverflowNorUnderflow) {
  std::mt19937_64 rng(9);
  for (double scale : {1e-150, 1e150}) {
    const Mat3 a = random_symmetric(rng, scale);
    const Vec3 ref = Eigen::SelfAdjointEigenSolver<Mat3>(a, Eigen::EigenvaluesOnly).eigenvalues();
    EXPECT_LE((symmetric_eigenvalues(a) - ref).cwiseAbs().maxCoeff(), 1e-13 * a.norm());
  }
}

TEST(SymmetricEigenvalues, ReadTheLowerTriangleAndPropagateNaN) {
  Mat3 a = Vec3(1.0, 2.0, 3.0).asDiagonal();
  a(0, 2) = 100.0;  // upper triangle: ignored
  EXPECT_NEAR(symmetric_eigenvalues(a)(2), 3.0, 1e-14);
  a(2, 0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(symmetric_eigenvalues(a).array().isNaN().all());
}

// The bits, pinned: the strain and step bounds rest on them, and Eigen's computeDirect (libm's
// atan2, cos and sin) gives other last bits on some processors. A change of method or a call
// falling back to libm moves this sum.
TEST(SymmetricEigenvalues, TheBitsArePinned) {
  std::mt19937_64 rng(17);
  std::uint64_t h = 1469598103934665603ull;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 e = symmetric_eigenvalues(random_symmetric(rng, 1.0 + k));
    for (int i = 0; i < 3; ++i) h = (h ^ std::bit_cast<std::uint64_t>(e(i))) * 1099511628211ull;
  }
  EXPECT_EQ(h, 15083904491854379506ull) << h;
}
