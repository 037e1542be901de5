#pragma once
// A list of integer lists in compressed rows: row r is items[start[r] .. start[r+1]).
#include <span>
#include <vector>

namespace mrsim {

struct CsrLists {
  std::vector<int> start{0};
  std::vector<int> items;

  int rows() const { return static_cast<int>(start.size()) - 1; }
  std::span<const int> row(int r) const {
    return {items.data() + start[r], static_cast<size_t>(start[r + 1] - start[r])};
  }
  void push_row(const std::vector<int>& row) {
    items.insert(items.end(), row.begin(), row.end());
    start.push_back(static_cast<int>(items.size()));
  }
};

}  // namespace mrsim
