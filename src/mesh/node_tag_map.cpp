#include "mesh/node_tag_map.hpp"

#include <algorithm>

namespace mrsim {

NodeTagMap::NodeTagMap(const std::vector<std::int64_t>& tags) {
  const std::int64_t max_tag = tags.empty() ? 0 : *std::max_element(tags.begin(), tags.end());
  use_dense_ = max_tag <= 4 * static_cast<std::int64_t>(tags.size()) + 1024;
  if (use_dense_) dense_.assign(static_cast<std::size_t>(max_tag) + 1, -1);
  for (std::size_t i = 0; i < tags.size(); ++i) {
    const int index = static_cast<int>(i);
    bool inserted = false;
    if (use_dense_) {
      int& slot = dense_[static_cast<std::size_t>(tags[i])];
      inserted = slot < 0;
      if (inserted) slot = index;
    } else {
      inserted = sparse_.emplace(tags[i], index).second;
    }
    if (!inserted && duplicate_ < 0) duplicate_ = tags[i];
  }
}

int NodeTagMap::find(std::int64_t tag) const {
  if (use_dense_) return (tag >= 0 && tag < static_cast<std::int64_t>(dense_.size())) ? dense_[tag] : -1;
  const auto it = sparse_.find(tag);
  return it == sparse_.end() ? -1 : it->second;
}

}  // namespace mrsim
