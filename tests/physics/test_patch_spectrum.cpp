// Semi-implicit time levels' per-point shares (physics/patch_spectrum.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <limits>

#include "physics/dense_spectrum.hpp"
#include "physics/level_model.hpp"
#include "physics/patch_spectrum.hpp"
#include "physics/spectral_bound.hpp"

namespace mrsim {
namespace {

using test_support::jittered_box;
using test_support::law_with;

// The largest eigenvalue of the principal submatrix of the dense operator `a` on `points`: every
// other point held (test_support::free_block).
double dense_patch_eigenvalue(const Eigen::MatrixXd& a, int num_points,
                              const std::vector<int>& points) {
  std::vector<std::uint8_t> held(num_points, 1);
  for (int p : points) held[p] = 0;
  return test_support::largest_eigenvalue(test_support::free_block(a, held));
}

// Each patch's operator is the principal submatrix of the level's filtered operator (the dense
// truth of tests/physics/dense_spectrum.hpp) on the point and its neighbours, so its largest
// eigenvalue is never above the level's λ_f (interlacing); the highest modes live at the scale
// of a tet, so the largest patch finds most of it.
TEST(PatchSpectrum, PatchesAreThePrincipalSubmatricesOfTheFilteredOperator) {
  const TetMesh mesh = jittered_box(6, 4, 3, 0.2, 7);
  for (double lambda : {0.0, 5.0e4, 5.0e5}) {
    LevelModel m = build_level_model(mesh, law_with(lambda, 1.0e4), true);
    prepare_semi_implicit_time_levels(m);
    const Eigen::MatrixXd a = test_support::dense_operator(m, m.K, +1);
    const double lf = test_support::largest_eigenvalue(a);
    const std::vector<double> l = patch_filtered_eigenvalues(m.adj, m.K, m.mass);
    for (int i = 0; i < m.num_points(); ++i) {
      std::vector<int> points{i};
      for (int e = m.adj.nbr_start[i]; e < m.adj.nbr_start[i + 1]; ++e)
        points.push_back(m.adj.nbr[e]);
      const double truth = dense_patch_eigenvalue(a, m.num_points(), points);
      ASSERT_NEAR(l[i], truth, 1e-9 * std::abs(lf)) << lambda << " point " << i;
    }
    const double top = *std::max_element(l.begin(), l.end());
    EXPECT_LE(top, lf * (1 + 1e-9)) << lambda;
    // What the time levels count: each point's share of its proven bound. Its largest covers the
    // level's λ_f with the margin of the one global step, also where the patches miss a mode
    // that spans the level (λ = 0: every patch's eigenvalue is negative; λ = 5·10⁴: the
    // patches' shares alone counted 0.79 of it).
    double counted = 0;
    for (int i = 0; i < m.num_points(); ++i)
      counted = std::max(counted, m.time_level_share[i] * m.star[i].stiffness / m.mass[i]);
    EXPECT_GE(counted, kSpectralMargin * lf * (1 - 1e-3)) << lambda;
    std::printf(
        "lambda %.0e: largest patch eigenvalue %.3f of the level's filtered one; the largest "
        "share counted %.2f of it\n",
        lambda, top / lf, counted / lf);
  }
}

// A held point is out of every patch (its mass infinite), and the shares stay between the floor
// and the thesis' quarter; where a point's own patch and its neighbours' say little is left
// explicit the share falls below the quarter.
TEST(PatchSpectrum, SharesLieBetweenTheFloorAndTheQuarter) {
  const TetMesh mesh = jittered_box(6, 4, 3, 0.2, 7);
  LevelModel m = build_level_model(mesh, law_with(5.0e4, 1.0e4), true);
  EXPECT_TRUE(m.time_level_share.empty()) << "only where time levels run";
  prepare_semi_implicit_time_levels(m);
  ASSERT_EQ(m.time_level_share.size(), static_cast<size_t>(m.num_points()));
  int below = 0;
  for (double s : m.time_level_share) {
    EXPECT_GE(s, kFilterStiffening);
    EXPECT_LE(s, kSemiImplicitShare);
    below += s < kSemiImplicitShare;
  }
  EXPECT_GT(below, m.num_points() / 2);
  std::vector<double> mass = m.mass;
  mass[0] = std::numeric_limits<double>::infinity();
  const std::vector<double> l = patch_filtered_eigenvalues(m.adj, m.K, mass);
  EXPECT_TRUE(std::isinf(l[0]) && l[0] < 0);
  const LevelModel explicit_model = build_level_model(mesh, law_with(5.0e4, 1.0e4), false);
  EXPECT_TRUE(explicit_model.time_level_share.empty());
}

}  // namespace
}  // namespace mrsim
