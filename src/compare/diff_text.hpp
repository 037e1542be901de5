#pragma once
// How one difference reads in the report: shapes ("[51, 3]" for HDF5, "[3386×3]" for VTK
// arrays), indices ("[17, 2]", or "point 345 component 2" when the axes have names) and the
// summary of an array diff with the values at its worst place, in their shortest exact form.
#include <optional>
#include <string>
#include <vector>

#include "compare/array_diff.hpp"
#include "compare/value_array.hpp"

namespace mrsim {

/// Shortest text that parses back to exactly `value` ("0.1", "1.0000000000000002e-05", "nan").
std::string number_text(double value);

/// "[51, 3]" (separator ", ") or "[3386×3]" (separator "×"); "scalar" for rank 0.
std::string shape_text(const Shape& shape, const std::string& separator = ", ");

/// Flat index `flat` of an array of `shape`: "[17, 2]", or with axis names
/// "point 17 component 2" (a last axis of extent 1 is not named: "point 17").
std::string index_text(std::size_t flat, const Shape& shape, const AxisNames& axes = {});

/// Element `i` of `v` as the report shows it ("0.12341", "121", "\"split\"").
std::string element_text(const ValueArray& v, std::size_t i);

/// Why two arrays cannot be compared element by element: different kinds or shapes;
/// nullopt when they can.
std::optional<std::string> layout_difference(const ValueArray& a, const ValueArray& b,
                                             const std::string& separator = ", ");

/// "3 of 51 values differ; max abs 1.2e-05 at [17] (A 0.1234, B 0.12341); max rel 9.7e-05 at
/// [17]", or for a single value "A 0.1234, B 0.12341 (abs 1e-05, rel 8.1e-05)".
std::string diff_text(const ArrayDiff& d, const ValueArray& a, const ValueArray& b,
                      const AxisNames& axes = {});

}  // namespace mrsim
