#pragma once
// Resolution of plain (unquoted) YAML scalars by the YAML 1.2 core schema: null, booleans,
// integers (decimal, 0o octal, 0x hex) and floats. yaml-cpp's event API hands over raw text;
// typing it here keeps the JSON faithful to what editors and the YAML 1.2 spec say.
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace mrsim::scenario {

/// A plain scalar that looks like a number but cannot be one (.nan, .inf, overflow).
struct ScalarError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Types a plain scalar; anything that is not null, bool, int or float stays a string.
/// Throws ScalarError for non-finite or out-of-range numbers.
nlohmann::json resolve_plain_scalar(const std::string& text);

}  // namespace mrsim::scenario
