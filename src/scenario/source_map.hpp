#pragma once
// Where each value of a scenario document came from, so that every error can name the file
// and the YAML line:column (or the `--set` override) that produced the offending value.
#include <map>
#include <string>

namespace mrsim::scenario {

struct Location {
  std::string origin;  // file name as the user gave it, or "--set key=value"
  int line = 0;        // 1-based; 0 when the origin has no meaningful position (overrides)
  int column = 0;      // 1-based
  int rank = 0;        // 0 for the file, k for the k-th override: orders messages by source
};

/// "file:12:3" or "--set a.b=1" (no position).
std::string format_location(const Location& location);

/// JSON pointer ("/material/lambda") -> location of its key (or of the value for list items
/// and the root). Lookups fall back to the nearest recorded ancestor, because defaults,
/// alias copies and missing keys have no position of their own.
class SourceMap {
 public:
  void set(const std::string& pointer, Location location);
  /// Removes `pointer` and everything below it (an override replaces a whole subtree).
  void erase_subtree(const std::string& pointer);
  const Location& at(const std::string& pointer) const;
  /// The location of `pointer` or of its nearest recorded ancestor; a default one if none.
  Location find(const std::string& pointer) const;

 private:
  std::map<std::string, Location> entries_;
};

}  // namespace mrsim::scenario
