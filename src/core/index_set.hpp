#pragma once
// The items a hot loop visits: either all of [0, n) or an explicit list (the active points of a
// level, the tets touching them). Loops written against it cost O(count), which is how a step
// follows the active set rather than the size of the meshes (product.md "Fast").
#include <vector>

namespace mrsim {

struct IndexSet {
  const int* ids = nullptr;  // nullptr: the identity 0..count-1
  int count = 0;

  static IndexSet all(int n) { return {nullptr, n}; }
  static IndexSet of(const std::vector<int>& list) {
    return {list.data(), static_cast<int>(list.size())};
  }
  int operator[](int k) const { return ids ? ids[k] : k; }
};

}  // namespace mrsim
