// Transcendentals with the same bits on every processor (core/portable_math.hpp): within 2 ulp
// of glibc's (itself within 1 ulp) over each function's range, IEEE special values, and a
// checksum of their bits that a call falling back to libm would change on some processor.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <random>

#include "core/portable_math.hpp"

using namespace mrsim;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Distance in units in the last place between two finite doubles of the same sign.
std::int64_t ulps(double a, double b) {
  if (a == b) return 0;
  const auto key = [](double v) {
    const auto bits = std::bit_cast<std::int64_t>(v);
    return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
  };
  const std::int64_t d = key(a) - key(b);
  return d < 0 ? -d : d;
}

struct Sweep {
  double lo, hi;
  int samples;
};

std::int64_t worst_ulps(const std::function<double(double)>& mine,
                        const std::function<double(double)>& libm, Sweep s) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pick(s.lo, s.hi);
  std::int64_t worst = 0;
  for (int i = 0; i < s.samples; ++i) {
    const double x = pick(rng);
    worst = std::max(worst, ulps(mine(x), libm(x)));
  }
  return worst;
}

}  // namespace

TEST(PortableMath, ExpIsWithinTwoUlpOfLibm) {
  const auto mine = [](double x) { return portable::exp(x); };
  const auto libm = [](double x) { return std::exp(x); };
  EXPECT_LE(worst_ulps(mine, libm, {-1.0, 1.0, 200000}), 2);
  EXPECT_LE(worst_ulps(mine, libm, {-700.0, 700.0, 200000}), 2);
  EXPECT_LE(worst_ulps(mine, libm, {-1e-8, 1e-8, 20000}), 1);
}

TEST(PortableMath, ExpSpecialValues) {
  EXPECT_EQ(portable::exp(0.0), 1.0);
  EXPECT_EQ(portable::exp(-0.0), 1.0);
  EXPECT_EQ(portable::exp(kInf), kInf);
  EXPECT_EQ(portable::exp(-kInf), 0.0);
  EXPECT_TRUE(std::isnan(portable::exp(kNaN)));
  EXPECT_EQ(portable::exp(710.0), kInf);
  EXPECT_EQ(portable::exp(-746.0), 0.0);
  // Near the overflow and in the subnormal range the scaling by 2^k still rounds once.
  EXPECT_LE(ulps(portable::exp(709.7), std::exp(709.7)), 2);
  EXPECT_LE(ulps(portable::exp(-740.0), std::exp(-740.0)), 1);
  EXPECT_LE(ulps(portable::exp(-708.5), std::exp(-708.5)), 2);
  EXPECT_LE(ulps(portable::exp(1.0), std::numbers::e), 1);
}

TEST(PortableMath, LogIsWithinTwoUlpOfLibm) {
  const auto mine = [](double x) { return portable::log(x); };
  const auto libm = [](double x) { return std::log(x); };
  EXPECT_LE(worst_ulps(mine, libm, {0.5, 2.0, 200000}), 2);
  EXPECT_LE(worst_ulps(mine, libm, {1e-300, 1e300, 200000}), 2);
  EXPECT_LE(worst_ulps(mine, libm, {1.0 - 1e-6, 1.0 + 1e-6, 20000}), 2);
  const auto exp_of = [](double e) { return std::exp2(e); };
  EXPECT_LE(worst_ulps([&](double e) { return portable::log(exp_of(e)); },
                       [&](double e) { return std::log(exp_of(e)); }, {-1070.0, 1020.0, 20000}),
            2);  // across every exponent, subnormals included
}

TEST(PortableMath, LogSpecialValues) {
  EXPECT_EQ(portable::log(1.0), 0.0);
  EXPECT_EQ(portable::log(0.0), -kInf);
  EXPECT_EQ(portable::log(-0.0), -kInf);
  EXPECT_EQ(portable::log(kInf), kInf);
  EXPECT_TRUE(std::isnan(portable::log(-1.0)));
  EXPECT_TRUE(std::isnan(portable::log(-kInf)));
  EXPECT_TRUE(std::isnan(portable::log(kNaN)));
  EXPECT_LE(ulps(portable::log(std::numbers::e), 1.0), 1);
  EXPECT_LE(ulps(portable::log(2.0), std::numbers::ln2), 1);
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_LE(ulps(portable::log(tiny), std::log(tiny)), 1);
}

TEST(PortableMath, SinAndCosAreWithinTwoUlpOfLibm) {
  for (const auto& [mine, libm] :
       {std::pair<std::function<double(double)>, std::function<double(double)>>{
            [](double x) { return portable::sin(x); }, [](double x) { return std::sin(x); }},
        {[](double x) { return portable::cos(x); }, [](double x) { return std::cos(x); }}}) {
    EXPECT_LE(worst_ulps(mine, libm, {-std::numbers::pi / 4, std::numbers::pi / 4, 200000}), 1);
    EXPECT_LE(worst_ulps(mine, libm, {-10.0, 10.0, 200000}), 2);
    EXPECT_LE(worst_ulps(mine, libm, {-1e5, 1e5, 200000}), 2);  // the Lanczos start vectors
  }
}

TEST(PortableMath, SinAndCosSpecialValues) {
  EXPECT_EQ(portable::sin(0.0), 0.0);
  EXPECT_TRUE(std::signbit(portable::sin(-0.0)));
  EXPECT_EQ(portable::cos(0.0), 1.0);
  EXPECT_EQ(portable::cos(-0.0), 1.0);
  EXPECT_EQ(portable::sin(1e-300), 1e-300);
  for (double x : {kInf, -kInf, kNaN}) {
    EXPECT_TRUE(std::isnan(portable::sin(x)));
    EXPECT_TRUE(std::isnan(portable::cos(x)));
  }
  // Beyond the reduction's exact range: no accuracy promised, but a value in [-1, 1].
  for (double x : {1e7, -3e12, 1e300}) {
    EXPECT_LE(std::abs(portable::sin(x)), 1.0);
    EXPECT_LE(std::abs(portable::cos(x)), 1.0);
  }
  // Odd and even, to the bit.
  for (double x : {0.3, 2.0, 17.5, 1000.25}) {
    EXPECT_EQ(portable::sin(-x), -portable::sin(x));
    EXPECT_EQ(portable::cos(-x), portable::cos(x));
  }
}

TEST(PortableMath, Atan2IsWithinTwoUlpOfLibmInEveryQuadrant) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pick(-5.0, 5.0);
  std::int64_t worst = 0;
  for (int i = 0; i < 400000; ++i) {
    const double y = pick(rng), x = pick(rng);
    worst = std::max(worst, ulps(portable::atan2(y, x), std::atan2(y, x)));
  }
  EXPECT_LE(worst, 2);
  // Very unequal sides: ratios near 0 and near infinity.
  for (double r : {1e-300, 1e-20, 1e-9, 1e9, 1e20, 1e300})
    for (double x : {1.0, -1.0}) EXPECT_LE(ulps(portable::atan2(r * x * x, x), std::atan2(r * x * x, x)), 2);
}

TEST(PortableMath, Atan2SpecialValuesFollowIeee) {
  const double pi = std::numbers::pi;
  EXPECT_EQ(portable::atan2(0.0, 1.0), 0.0);
  EXPECT_TRUE(std::signbit(portable::atan2(-0.0, 1.0)));
  EXPECT_EQ(portable::atan2(0.0, -1.0), pi);
  EXPECT_EQ(portable::atan2(-0.0, -1.0), -pi);
  EXPECT_EQ(portable::atan2(0.0, 0.0), 0.0);
  EXPECT_EQ(portable::atan2(0.0, -0.0), pi);
  EXPECT_EQ(portable::atan2(-0.0, -0.0), -pi);
  EXPECT_EQ(portable::atan2(1.0, 0.0), pi / 2);
  EXPECT_EQ(portable::atan2(-1.0, -0.0), -pi / 2);
  EXPECT_EQ(portable::atan2(kInf, kInf), pi / 4);
  EXPECT_EQ(portable::atan2(kInf, -kInf), 3 * pi / 4);
  EXPECT_EQ(portable::atan2(-kInf, 1.0), -pi / 2);
  EXPECT_EQ(portable::atan2(1.0, kInf), 0.0);
  EXPECT_EQ(portable::atan2(1.0, -kInf), pi);
  EXPECT_EQ(portable::atan2(1.0, 1.0), pi / 4);
  EXPECT_TRUE(std::isnan(portable::atan2(kNaN, 1.0)));
  EXPECT_TRUE(std::isnan(portable::atan2(1.0, kNaN)));
}

TEST(PortableMath, AcosIsWithinTwoUlpOfLibm) {
  const auto mine = [](double x) { return portable::acos(x); };
  const auto libm = [](double x) { return std::acos(x); };
  EXPECT_LE(worst_ulps(mine, libm, {-1.0, 1.0, 200000}), 2);
  EXPECT_EQ(portable::acos(1.0), 0.0);
  EXPECT_EQ(portable::acos(-1.0), std::numbers::pi);
  EXPECT_TRUE(std::isnan(portable::acos(1.0 + 1e-15)));
  EXPECT_TRUE(std::isnan(portable::acos(kNaN)));
}

// The bits themselves, pinned: they are what the golden files rest on. A function that called
// into libm (or changed) would move this sum on some processor, or on this one.
TEST(PortableMath, TheBitsArePinned) {
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&](double v) { h = (h ^ std::bit_cast<std::uint64_t>(v)) * 1099511628211ull; };
  for (int i = 0; i < 4000; ++i) {
    const double x = -20.0 + i * 0.01003;
    mix(portable::exp(x));
    mix(portable::log(std::abs(x) + 1e-3));
    mix(portable::sin(x * 7.3));
    mix(portable::cos(x * 7.3));
    mix(portable::atan2(x, 3.0 - 0.25 * x));
  }
  EXPECT_EQ(h, 2174029323807181429ull) << h;
}
