#include "compare/array_diff.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace mrsim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// |a - b| as the report shows it: a NaN against a number, or two different infinities, are
// infinitely far apart.
double absolute_gap(double a, double b) {
  const double gap = std::fabs(a - b);
  return std::isnan(gap) ? kInfinity : gap;
}

double relative_gap(double a, double b) {
  const double scale = std::max(std::fabs(a), std::fabs(b));
  const double gap = absolute_gap(a, b) / scale;
  return std::isnan(gap) || scale == 0 ? kInfinity : gap;
}

// Records element i as different; `abs` and `rel` are its gaps (rel < 0: not tracked).
void record(ArrayDiff& d, std::size_t i, double abs, double rel) {
  if (d.differing++ == 0) {
    d.first = d.abs_at = d.rel_at = i;
    d.max_abs = abs;
    d.max_rel = rel;
    return;
  }
  if (abs > d.max_abs) {
    d.max_abs = abs;
    d.abs_at = i;
  }
  if (rel > d.max_rel) {
    d.max_rel = rel;
    d.rel_at = i;
  }
}

void diff_reals(const std::vector<double>& a, const std::vector<double>& b,
                const Tolerance& tolerance, ArrayDiff& d) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!within(a[i], b[i], tolerance))
      record(d, i, absolute_gap(a[i], b[i]), relative_gap(a[i], b[i]));
  }
}

void diff_integers(const std::vector<std::int64_t>& a, const std::vector<std::int64_t>& b,
                   ArrayDiff& d) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    // In double: the int64 subtraction could overflow, and the gap is only for display.
    if (a[i] != b[i])
      record(d, i, std::fabs(static_cast<double>(a[i]) - static_cast<double>(b[i])), -1);
  }
}

void diff_texts(const std::vector<std::string>& a, const std::vector<std::string>& b,
                ArrayDiff& d) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] != b[i]) record(d, i, 0, -1);
  }
}

std::size_t stored_count(const ValueArray& v) {
  switch (v.kind) {
    case ValueKind::Real:
      return v.reals.size();
    case ValueKind::Integer:
      return v.integers.size();
    case ValueKind::Text:
    case ValueKind::Bytes:
      return v.texts.size();
  }
  return 0;
}

}  // namespace

ArrayDiff diff_arrays(const ValueArray& a, const ValueArray& b, const Tolerance& tolerance) {
  if (a.kind != b.kind || stored_count(a) != stored_count(b)) {
    throw std::invalid_argument("diff_arrays: arrays of different kinds or sizes");
  }
  ArrayDiff d;
  d.total = stored_count(a);
  switch (a.kind) {
    case ValueKind::Real:
      diff_reals(a.reals, b.reals, tolerance, d);
      break;
    case ValueKind::Integer:
      diff_integers(a.integers, b.integers, d);
      break;
    case ValueKind::Text:
    case ValueKind::Bytes:
      diff_texts(a.texts, b.texts, d);
      break;
  }
  return d;
}

std::vector<std::size_t> multi_index(std::size_t flat, const Shape& shape) {
  std::vector<std::size_t> index(shape.size());
  for (std::size_t k = shape.size(); k-- > 0;) {
    const std::size_t extent = shape[k] == 0 ? 1 : shape[k];
    index[k] = flat % extent;
    flat /= extent;
  }
  return index;
}

}  // namespace mrsim
