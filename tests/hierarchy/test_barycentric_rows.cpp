// The ghosts' two per-step passes (hierarchy/barycentric_rows.hpp): the AVX2 build gives the
// baseline build's bits, and both give the sums they stand for.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "hierarchy/barycentric_rows.hpp"
#include "support/same_bits.hpp"

using namespace mrsim;

namespace {

struct Rows {
  std::vector<int> points;  // into the targets, some skipped, in no order
  std::vector<std::array<int, 4>> source;
  std::vector<std::array<double, 4>> bary;
  std::vector<Vec3> su, sv;
};

// Sources of every magnitude and sign (signed weights: a ghost outside its source mesh), the
// last source point read (its neighbour past the array is not there), a -0 and a subnormal.
Rows random_rows(int targets, int sources, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1), exponent(-30, 30);
  std::uniform_int_distribution<int> pick(0, sources - 1);
  Rows r;
  r.source.resize(targets);
  r.bary.resize(targets);
  for (int p = 0; p < targets; ++p) {
    if (p % 5 != 3) r.points.push_back(p);
    for (int k = 0; k < 4; ++k) r.source[p][k] = pick(rng);
    double sum = 0;
    for (int k = 0; k < 3; ++k) sum += r.bary[p][k] = unit(rng) * 1.5;
    r.bary[p][3] = 1 - sum;
  }
  r.source[targets / 2] = {sources - 1, 0, sources - 1, 1};
  std::shuffle(r.points.begin(), r.points.end(), rng);
  const auto value = [&] { return unit(rng) * std::pow(10.0, exponent(rng)); };
  for (int s = 0; s < sources; ++s) {
    r.su.emplace_back(value(), value(), value());
    r.sv.emplace_back(value(), value(), value());
  }
  r.su[0].x() = -0.0;
  r.sv[1].z() = std::numeric_limits<double>::denorm_min();
  return r;
}

using test::same_bits;

bool runs_avx2() { return row_build() == RowBuild::Avx2; }

}  // namespace

TEST(BarycentricRows, InterpolateGivesTheWeightedSumsOfTheSources) {
  const Rows r = random_rows(300, 40, 1);
  std::vector<Vec3> tu(300, Vec3::Constant(7)), tv = tu;
  interpolate_rows(row_build(), r.points, r.source.data(), r.bary.data(), r.su.data(),
                   r.sv.data(), tu.data(), tv.data());
  for (int p = 0; p < 300; ++p) {
    if (p % 5 == 3) {  // not listed: untouched
      EXPECT_EQ(tu[p], Vec3::Constant(7));
      continue;
    }
    Vec3 u = Vec3::Zero(), v = Vec3::Zero();  // 0 + b₀s₀ is b₀s₀: the same sums, in order
    for (int k = 0; k < 4; ++k) {
      u += r.bary[p][k] * r.su[r.source[p][k]];
      v += r.bary[p][k] * r.sv[r.source[p][k]];
    }
    EXPECT_EQ(tu[p], u) << p;
    EXPECT_EQ(tv[p], v) << p;
  }
}

TEST(BarycentricRows, ScatterIsTheTransposeOfInterpolate) {
  // Σ_p from[p]·(interpolated u)[p] = Σ_s (scattered from)[s]·u[s]: virtual work unchanged.
  Rows r = random_rows(200, 30, 2);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (Vec3& u : r.su) u = Vec3(unit(rng), unit(rng), unit(rng));
  std::vector<Vec3> from(200), to(30, Vec3::Zero()), tu(200, Vec3::Zero()), tv = tu;
  for (Vec3& f : from) f = Vec3(unit(rng), unit(rng), unit(rng));
  interpolate_rows(row_build(), r.points, r.source.data(), r.bary.data(), r.su.data(),
                   r.su.data(), tu.data(), tv.data());
  scatter_rows(row_build(), r.points, r.source.data(), r.bary.data(), from.data(), to.data());
  double ghost_side = 0, source_side = 0;
  for (int p : r.points) ghost_side += from[p].dot(tu[p]);
  for (int s = 0; s < 30; ++s) source_side += to[s].dot(r.su[s]);
  EXPECT_NEAR(ghost_side, source_side, 1e-12 * 200);
  EXPECT_NE(source_side, 0.0);
}

TEST(BarycentricRows, Avx2BuildGivesTheBaselineBits) {
  if (!runs_avx2()) GTEST_SKIP() << "the AVX2 build does not run here (processor or MRSIM_KERNEL)";
  for (unsigned seed = 10; seed < 14; ++seed) {
    const Rows r = random_rows(500, 60, seed);
    std::vector<Vec3> bu(500, Vec3::Zero()), bv = bu, au = bu, av = bu;
    interpolate_rows(RowBuild::Baseline, r.points, r.source.data(), r.bary.data(), r.su.data(),
                     r.sv.data(), bu.data(), bv.data());
    interpolate_rows(RowBuild::Avx2, r.points, r.source.data(), r.bary.data(), r.su.data(),
                     r.sv.data(), au.data(), av.data());
    EXPECT_TRUE(same_bits(bu, au)) << "seed " << seed;
    EXPECT_TRUE(same_bits(bv, av)) << "seed " << seed;
    // The scatter adds into what is there, and sources repeat across rows: order matters. The
    // rows' own values (one per target point): the interpolated ones, of every magnitude.
    std::vector<Vec3> bt = r.sv, at = r.sv;
    scatter_rows(RowBuild::Baseline, r.points, r.source.data(), r.bary.data(), bu.data(),
                 bt.data());
    scatter_rows(RowBuild::Avx2, r.points, r.source.data(), r.bary.data(), bu.data(), at.data());
    EXPECT_TRUE(same_bits(bt, at)) << "seed " << seed;
    EXPECT_FALSE(same_bits(bt, r.sv));
  }
}
