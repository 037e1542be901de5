#include "scenario/source_map.hpp"

#include "scenario/json_path.hpp"

namespace mrsim::scenario {

std::string format_location(const Location& location) {
  if (location.line <= 0) return location.origin;
  return location.origin + ":" + std::to_string(location.line) + ":" +
         std::to_string(location.column);
}

void SourceMap::set(const std::string& pointer, Location location) {
  entries_[pointer] = std::move(location);
}

void SourceMap::erase_subtree(const std::string& pointer) {
  // Pointers below `pointer` sort right after it and start with "pointer/".
  auto it = entries_.lower_bound(pointer);
  while (it != entries_.end() && is_same_or_below(it->first, pointer)) it = entries_.erase(it);
}

const Location& SourceMap::at(const std::string& pointer) const { return entries_.at(pointer); }

Location SourceMap::find(const std::string& pointer) const {
  std::string current = pointer;
  while (true) {
    if (auto it = entries_.find(current); it != entries_.end()) return it->second;
    if (current.empty()) return {};
    current = parent_pointer(current);
  }
}

}  // namespace mrsim::scenario
