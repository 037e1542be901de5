#include "core/portable_math.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

// Only +, -, *, /, sqrt and bit operations below: no call into libm, whose build differs by
// processor (core/portable_math.hpp). The constants are the values' nearest doubles; a *_hi part
// has trailing zero bits where a product with a small integer must be exact.

namespace mrsim::portable {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

constexpr double kInvLn2 = 1.4426950408889634;
constexpr double kLn2Hi = 0.6931471803691238;  // 32 bits: k * kLn2Hi exact for |k| < 2^21
constexpr double kLn2Lo = 1.9082149292705877e-10;
constexpr double kSqrt2 = 1.4142135623730951;

constexpr double kPiHi = 3.141592653589793, kPiLo = 1.2246467991473532e-16;
constexpr double kPio2Hi = 1.5707963267948966, kPio2Lo = 6.123233995736766e-17;
constexpr double kPio4 = 0.7853981633974483;
constexpr double kTwoOverPi = 0.6366197723675814;
// pi/2 in three 33-bit parts: k * part exact for |k| < 2^20 (|x| below about 1.6e6).
constexpr double kPio2Part1 = 1.5707963267341256, kPio2Part2 = 6.077100506303966e-11,
                 kPio2Part3 = 2.0222662487959506e-21;

// atan(j/8), j = 0..8, as value + correction.
constexpr double kAtanHi[9] = {0.0,
                               0.12435499454676144,
                               0.24497866312686414,
                               0.35877067027057225,
                               0.4636476090008061,
                               0.5585993153435624,
                               0.6435011087932844,
                               0.7188299996216245,
                               0.7853981633974483};
constexpr double kAtanLo[9] = {0.0,
                               -3.1253241424539383e-18,
                               1.0698755618734451e-17,
                               -2.4623815582638635e-17,
                               2.2698777452961687e-17,
                               -5.4556305485916264e-18,
                               1.5834785051444286e-17,
                               -2.1478388444456983e-17,
                               3.061616997868383e-17};

// 2^k for a normal exponent, k in [-1022, 1023].
double pow2(int k) { return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52); }

// v * 2^k, v in [0.5, 2), k in [-1076, 1025]: at most one rounding (in the subnormal range).
double scaled(double v, int k) {
  if (k > 1023) return (v * pow2(1023)) * pow2(k - 1023);
  if (k < -1022) return (v * pow2(k + 54)) * pow2(-54);
  return v * pow2(k);
}

// c[0] x^(n-1) + ... + c[n-1] by Horner's rule, highest power first: every polynomial below is
// evaluated this one way, so its bits follow from its coefficients alone.
template <std::size_t N>
double horner(double x, const std::array<double, N>& c) {
  double p = c[0];
  for (std::size_t k = 1; k < N; ++k) p = p * x + c[k];
  return p;
}

// Nearest integer to t (halves away from zero), |t| < 2^62.
std::int64_t nearest(double t) {
  return static_cast<std::int64_t>(t >= 0 ? t + 0.5 : t - 0.5);
}

// sin and cos on |r| <= pi/4 (plus the reduction's rounding): Taylor series to r^21 / r^20,
// whose first omitted term is below 2^-70 of the value there.
// sin r = r + r z (-1/3! + z/5! - ... + z^9/21!), z = r^2.
constexpr std::array<double, 10> kSinTail = {
    1.0 / 51090942171709440000.0, -1.0 / 121645100408832000.0, 1.0 / 355687428096000.0,
    -1.0 / 1307674368000.0,       1.0 / 6227020800.0,           -1.0 / 39916800.0,
    1.0 / 362880.0,               -1.0 / 5040.0,                1.0 / 120.0,
    -1.0 / 6.0};
// cos r = 1 - (z/2 - z^2 (1/4! - z/6! + ... + z^8/20!)).
constexpr std::array<double, 9> kCosTail = {
    1.0 / 2432902008176640000.0, -1.0 / 6402373705728000.0, 1.0 / 20922789888000.0,
    -1.0 / 87178291200.0,        1.0 / 479001600.0,         -1.0 / 3628800.0,
    1.0 / 40320.0,               -1.0 / 720.0,              1.0 / 24.0};
// exp r = 1 + (r + r^2 (1/2! + r/3! + ... + r^12/14!)).
constexpr std::array<double, 13> kExpTail = {
    1.0 / 87178291200.0, 1.0 / 6227020800.0, 1.0 / 479001600.0, 1.0 / 39916800.0,
    1.0 / 3628800.0,     1.0 / 362880.0,     1.0 / 40320.0,     1.0 / 5040.0,
    1.0 / 720.0,         1.0 / 120.0,        1.0 / 24.0,        1.0 / 6.0,
    0.5};
// log(1 + f) = f - s (f - R), R = z (2/3 + 2z/5 + ... + 2z^11/25), s = f / (2 + f), z = s^2.
constexpr std::array<double, 12> kLogSeries = {2.0 / 25, 2.0 / 23, 2.0 / 21, 2.0 / 19,
                                               2.0 / 17, 2.0 / 15, 2.0 / 13, 2.0 / 11,
                                               2.0 / 9,  2.0 / 7,  2.0 / 5,  2.0 / 3};
// atan u = u + u z (-1/3 + z/5 - ... + z^7/17), z = u^2.
constexpr std::array<double, 8> kAtanTail = {1.0 / 17, -1.0 / 15, 1.0 / 13, -1.0 / 11,
                                             1.0 / 9,  -1.0 / 7,  1.0 / 5,  -1.0 / 3};

double sin_near_zero(double r) {
  const double z = r * r;
  return r + r * z * horner(z, kSinTail);
}

double cos_near_zero(double r) {
  const double z = r * r;
  return 1.0 - (0.5 * z - z * z * horner(z, kCosTail));
}

struct Reduced {
  double r;      // x - k pi/2, |r| <= pi/4 (about)
  int quadrant;  // k mod 4
};

Reduced reduce(double x) {
  const double t = x * kTwoOverPi;
  if (!(std::abs(t) < 0x1p62)) {
    // Every double this large is an even integer multiple of far more than pi: no accuracy
    // is left, only determinism. The quadrant from the exact remainder of t by 4.
    const double k = t;
    const int q = static_cast<int>(std::fmod(std::abs(k), 4.0));
    return {0.0, k < 0 ? (4 - q) & 3 : q};
  }
  const std::int64_t k = nearest(t);
  const double kd = static_cast<double>(k);
  const double r = ((x - kd * kPio2Part1) - kd * kPio2Part2) - kd * kPio2Part3;
  return {r, static_cast<int>(k & 3)};
}

// atan on u in [-1/16, 1/16]: series to u^17, first omitted term below 2^-90.
double atan_near_zero(double u) {
  const double z = u * u;
  return u + u * z * horner(z, kAtanTail);
}

// atan(t), t in [0, 1]: atan(c) + atan((t - c) / (1 + t c)) with c the nearest eighth, so
// that |u| <= 1/16 (t - c is exact: t and c within a factor 2 of each other).
double atan_unit(double t) {
  const int j = static_cast<int>(t * 8 + 0.5);
  if (j == 0) return atan_near_zero(t);
  const double c = j / 8.0;
  const double u = (t - c) / (1.0 + t * c);
  return kAtanHi[j] + (kAtanLo[j] + atan_near_zero(u));
}

}  // namespace

double exp(double x) {
  if (x != x) return x;
  if (x > 709.782712893384) return kInf;  // beyond log(DBL_MAX)
  if (x < -745.1332191019412) return 0.0;  // below half the smallest subnormal
  const std::int64_t k = nearest(x * kInvLn2);
  const double kd = static_cast<double>(k);
  const double r = (x - kd * kLn2Hi) - kd * kLn2Lo;  // |r| <= ln2 / 2 (about)
  // exp(r): Taylor series to r^14, first omitted term below 2^-70 of the value.
  const double e_r = 1.0 + (r + r * r * horner(r, kExpTail));
  return scaled(e_r, static_cast<int>(k));
}

double log(double x) {
  if (x != x) return x;
  if (x < 0) return kNaN;
  if (x == 0) return -kInf;
  if (x == kInf) return x;
  int e = 0;
  if (x < 0x1p-1022) {  // subnormal: bring it into the normal range first (exact)
    x *= 0x1p54;
    e = -54;
  }
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  e += static_cast<int>(bits >> 52) - 1023;
  double m = std::bit_cast<double>((bits & 0x000FFFFFFFFFFFFFull) | (std::uint64_t{1023} << 52));
  if (m > kSqrt2) {  // m in [sqrt(2)/2, sqrt(2)]
    m *= 0.5;
    ++e;
  }
  // log(1 + f) = 2 atanh(s), s = f / (2 + f): f - s (f - R), R = sum 2 z^n / (2n + 1), z = s^2
  // <= 0.0295, to z^12.
  const double f = m - 1.0;  // exact
  const double s = f / (2.0 + f), z = s * s;
  const double R = z * horner(z, kLogSeries);
  const double log_m = f - s * (f - R);
  const double ed = e;
  return ed * kLn2Hi + (ed * kLn2Lo + log_m);
}

double sin(double x) {
  if (!(std::abs(x) <= std::numeric_limits<double>::max())) return x - x;  // NaN, +-inf
  if (x == 0) return x;  // keeps the sign of zero
  const Reduced red = reduce(x);
  switch (red.quadrant) {
    case 0: return sin_near_zero(red.r);
    case 1: return cos_near_zero(red.r);
    case 2: return -sin_near_zero(red.r);
    default: return -cos_near_zero(red.r);
  }
}

double cos(double x) {
  if (!(std::abs(x) <= std::numeric_limits<double>::max())) return x - x;
  const Reduced red = reduce(x);
  switch (red.quadrant) {
    case 0: return cos_near_zero(red.r);
    case 1: return -sin_near_zero(red.r);
    case 2: return -cos_near_zero(red.r);
    default: return sin_near_zero(red.r);
  }
}

double atan2(double y, double x) {
  if (x != x || y != y) return x + y;
  const bool left = std::signbit(x);
  const double ax = std::abs(x), ay = std::abs(y);
  double a;  // the angle for |y|, in [0, pi]
  if (ay == 0) {
    a = left ? kPiHi : 0.0;
  } else if (ax == kInf) {
    a = ay == kInf ? (left ? 3 * kPio4 : kPio4) : (left ? kPiHi : 0.0);
  } else if (ay == kInf || ax == 0) {
    a = kPio2Hi;
  } else if (ay <= ax) {
    const double t = atan_unit(ay / ax);
    a = left ? (kPiHi - t) + kPiLo : t;
  } else {
    const double t = atan_unit(ax / ay);
    a = left ? (kPio2Hi + t) + kPio2Lo : (kPio2Hi - t) + kPio2Lo;
  }
  return std::signbit(y) ? -a : a;
}

double acos(double x) {
  if (!(std::abs(x) <= 1.0)) return kNaN;
  return atan2(std::sqrt((1.0 - x) * (1.0 + x)), x);
}

}  // namespace mrsim::portable
