#pragma once
// Union of two sorted index lists (the working lists of the hierarchy are kept sorted).
#include <algorithm>
#include <iterator>
#include <vector>

namespace mrsim {

/// out = a ∪ b, sorted, without duplicates. No allocation once out has grown.
inline void merge_sorted(const std::vector<int>& a, const std::vector<int>& b,
                         std::vector<int>& out) {
  out.clear();
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
}

}  // namespace mrsim
