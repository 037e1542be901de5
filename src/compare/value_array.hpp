#pragma once
// One named array of values as read from a run's output (an HDF5 dataset or attribute, a VTK
// data array), in a form both readers share so that one diff serves them all. Values are held
// in the widest type of their kind: every integer as int64 (exact for every counter mrsim
// writes), every float as double.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mrsim {

using Shape = std::vector<std::size_t>;  // empty: a scalar

/// Names of the axes of an array, outermost first ({"point", "component"}); empty: an index
/// is written as [i, j, ...].
using AxisNames = std::vector<std::string>;

enum class ValueKind {
  Real,     // floating point: compared with the tolerance
  Integer,  // compared exactly
  Text,     // compared exactly
  Bytes,    // any other HDF5 type (compound, enum, ...): each element's raw bytes, exactly
};

struct ValueArray {
  ValueKind kind = ValueKind::Real;
  Shape shape;
  std::vector<double> reals;           // kind Real
  std::vector<std::int64_t> integers;  // kind Integer
  std::vector<std::string> texts;      // kind Text, Bytes (one string per element)
};

/// Product of the extents (1 for a scalar).
std::size_t element_count(const Shape& shape);

/// "float", "integer", "string", "binary".
const char* kind_name(ValueKind kind);

}  // namespace mrsim
