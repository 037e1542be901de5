// The rule by which floats are equal (tolerance.hpp) and the integer exactness of array_diff.
#include <gtest/gtest.h>

#include <limits>

#include "compare/array_diff.hpp"
#include "compare/tolerance.hpp"

namespace mrsim {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Tolerance, ZeroToleranceMeansEqualValues) {
  EXPECT_TRUE(within(0.1, 0.1, {}));
  EXPECT_FALSE(within(0.1, std::nextafter(0.1, 1.0), {}));
  EXPECT_TRUE(within(0.0, -0.0, {}));
}

TEST(Tolerance, AbsoluteBound) {
  const Tolerance t{0, 1e-3};
  EXPECT_TRUE(within(1.0, 1.001, t));
  EXPECT_TRUE(within(1000.0, 1000.0009, t));
  EXPECT_FALSE(within(1.0, 1.0021, t));
}

TEST(Tolerance, RelativeToTheLargerMagnitude) {
  const Tolerance t{0.01, 0};
  EXPECT_TRUE(within(100.0, 101.0, t));   // 1 <= 0.01 * 101
  EXPECT_TRUE(within(101.0, 100.0, t));   // symmetric
  EXPECT_FALSE(within(100.0, 102.0, t));  // 2 > 1.02
  EXPECT_FALSE(within(0.0, 1e-300, t));   // relative alone never forgives a zero
  EXPECT_TRUE(within(0.0, 1e-300, {0.01, 1e-300}));
}

TEST(Tolerance, NaNEqualsOnlyNaN) {
  EXPECT_TRUE(within(kNaN, kNaN, {}));
  EXPECT_FALSE(within(kNaN, 1.0, {1e9, 1e9}));
  EXPECT_FALSE(within(1.0, kNaN, {1e9, 1e9}));
}

TEST(Tolerance, InfinityEqualsOnlyTheSameInfinity) {
  EXPECT_TRUE(within(kInf, kInf, {}));
  EXPECT_TRUE(within(-kInf, -kInf, {}));
  EXPECT_FALSE(within(kInf, -kInf, {1e9, 1e9}));
  EXPECT_FALSE(within(kInf, 1e308, {1e9, 1e9}));
}

TEST(Tolerance, IntegersAreExactWhateverTheTolerance) {
  const ValueArray a{ValueKind::Integer, {3}, {}, {10, 20, 30}, {}};
  const ValueArray b{ValueKind::Integer, {3}, {}, {10, 21, 30}, {}};
  const ArrayDiff d = diff_arrays(a, b, {1e6, 1e6});
  EXPECT_EQ(d.differing, 1u);
  EXPECT_EQ(d.abs_at, 1u);
  EXPECT_EQ(d.max_abs, 1.0);
  EXPECT_FALSE(diff_arrays(a, a, {}).any());
}

TEST(Tolerance, FloatsUseTheToleranceInArrays) {
  const ValueArray a{ValueKind::Real, {3}, {1.0, 2.0, kNaN}, {}, {}};
  const ValueArray b{ValueKind::Real, {3}, {1.0 + 1e-9, 2.0, kNaN}, {}, {}};
  EXPECT_EQ(diff_arrays(a, b, {}).differing, 1u);
  EXPECT_FALSE(diff_arrays(a, b, {0, 1e-8}).any());
  EXPECT_FALSE(diff_arrays(a, b, {1e-8, 0}).any());
}

}  // namespace
}  // namespace mrsim
