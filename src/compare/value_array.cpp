#include "compare/value_array.hpp"

namespace mrsim {

std::size_t element_count(const Shape& shape) {
  std::size_t count = 1;
  for (const std::size_t extent : shape) count *= extent;
  return count;
}

const char* kind_name(ValueKind kind) {
  switch (kind) {
    case ValueKind::Real:
      return "float";
    case ValueKind::Integer:
      return "integer";
    case ValueKind::Text:
      return "string";
    case ValueKind::Bytes:
      return "binary";
  }
  return "unknown";
}

}  // namespace mrsim
