#pragma once
// A list of integer lists in compressed rows: row r is items[start[r] .. start[r+1]).
#include <cstddef>
#include <span>
#include <vector>

namespace mrsim {

/// Do `rows` compressed rows of `items` entries have these starts: start[0..rows] from 0 to
/// `items`, never decreasing? (Rows read back from a file are checked before use.)
inline bool rows_add_up(std::span<const int> start, std::size_t rows, std::size_t items) {
  if (start.size() != rows + 1 || start.front() != 0 || start.back() != static_cast<int>(items))
    return false;
  for (std::size_t r = 0; r < rows; ++r)
    if (start[r + 1] < start[r]) return false;
  return true;
}

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
