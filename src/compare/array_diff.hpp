#pragma once
// Element-by-element comparison of two arrays of the same kind and shape: how many values
// differ, the first one, and where the largest absolute (and, for floats, relative)
// difference is, as flat row-major indices; multi_index() turns one into [i, j, ...].
#include <cstddef>
#include <vector>

#include "compare/tolerance.hpp"
#include "compare/value_array.hpp"

namespace mrsim {

struct ArrayDiff {
  std::size_t total = 0;      // elements compared
  std::size_t differing = 0;  // elements that differ
  std::size_t first = 0;      // flat index of the first difference
  std::size_t abs_at = 0;     // Real, Integer: flat index of the largest |a - b|
  double max_abs = 0;         // +inf where a NaN meets a number or the infinities differ
  std::size_t rel_at = 0;     // Real: flat index of the largest |a - b| / max(|a|, |b|)
  double max_rel = 0;
  bool any() const { return differing > 0; }
};

/// Floats by `tolerance`; integers, strings and bytes exactly, whatever the tolerance
/// (integers are counters: a tolerance that hid one event or evaluation would hide a
/// behaviour change). Requires the same kind and element count (throws std::invalid_argument).
ArrayDiff diff_arrays(const ValueArray& a, const ValueArray& b, const Tolerance& tolerance);

/// Row-major flat index -> one index per dimension: 53 in [10, 3] -> {17, 2}; {} for a scalar.
std::vector<std::size_t> multi_index(std::size_t flat, const Shape& shape);

}  // namespace mrsim
