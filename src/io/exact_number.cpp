#include "io/exact_number.hpp"

#include <array>
#include <charconv>

namespace mrsim {

std::string exact_number(double value) {
  // std::to_chars without a precision gives the shortest string that round-trips exactly
  // (as %.17g does, but without the noise digits: 0.04 rather than 0.040000000000000001).
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

}  // namespace mrsim
