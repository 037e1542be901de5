#pragma once
// Bit-for-bit equality of doubles and of arrays of plain values (a cached or vectorised result
// against the one computed plainly): == would call -0 and +0 equal and NaN unequal to itself.
#include <cstring>
#include <vector>

namespace mrsim::test {

inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

}  // namespace mrsim::test
