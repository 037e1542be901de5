#include "meshing/triangle_grid.hpp"

#include <cmath>

namespace mrsim {
namespace {

constexpr std::int64_t kOffset = std::int64_t{1} << 20;  // cell coordinates fit in 21 bits

std::uint64_t cell_key(std::int64_t i, std::int64_t j, std::int64_t k) {
  auto wrap = [](std::int64_t c) { return static_cast<std::uint64_t>((c + kOffset) & ((kOffset << 1) - 1)); };
  return (wrap(i) << 42) | (wrap(j) << 21) | wrap(k);
}

}  // namespace

template <typename Visit>
void TriangleGrid::for_cells(const BoundingBox& box, Visit visit) const {
  std::int64_t lo[3], hi[3];
  for (int d = 0; d < 3; ++d) {
    lo[d] = static_cast<std::int64_t>(std::floor(box.lo[d] / cell_));
    hi[d] = static_cast<std::int64_t>(std::floor(box.hi[d] / cell_));
  }
  for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
    for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
      for (std::int64_t k = lo[2]; k <= hi[2]; ++k) visit(cell_key(i, j, k));
}

void TriangleGrid::insert(const BoundingBox& box, int triangle) {
  if (static_cast<std::size_t>(triangle) >= seen_.size()) seen_.resize(triangle + 1, 0);
  for_cells(box, [&](std::uint64_t key) { cells_[key].push_back(triangle); });
}

void TriangleGrid::query(const BoundingBox& box, std::vector<int>& out) {
  out.clear();
  ++stamp_;
  for_cells(box, [&](std::uint64_t key) {
    const auto it = cells_.find(key);
    if (it == cells_.end()) return;
    for (int t : it->second) {
      if (seen_[t] == stamp_) continue;
      seen_[t] = stamp_;
      out.push_back(t);
    }
  });
}

}  // namespace mrsim
