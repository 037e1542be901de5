#include "physics/packed_tets.hpp"

#include <numeric>

namespace mrsim {

void PackedTets::pack(const TetGeometry& geo, const std::vector<int>& ids, bool closed_list) {
  source = ids.data();
  closed = closed_list;
  count = static_cast<int>(ids.size());
  tets.resize(count);
  grad.resize(count);
  volume.resize(count);
  scales.resize(geo.scales.empty() ? 0 : count);
  weight.resize(count);
  order.resize(count);
  weight_source = nullptr;
  for (int k = 0; k < count; ++k) {
    tets[k] = geo.tets[ids[k]];
    grad[k] = geo.grad[ids[k]];
    volume[k] = geo.volume[ids[k]];
    if (!scales.empty()) scales[k] = geo.scales[ids[k]];
  }
  std::iota(order.begin(), order.end(), 0);
}

void PackedTets::clear() {
  source = nullptr;
  count = 0;
  tets.clear();
  grad.clear();
  volume.clear();
  scales.clear();
  weight.clear();
  weight_source = nullptr;
  order.clear();
  closed = false;
}

}  // namespace mrsim
