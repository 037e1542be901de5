#include "physics/packed_tets.hpp"

#include <numeric>

namespace mrsim {

void PackedTets::pack(const TetGeometry& geo, const std::vector<int>& ids) {
  source = ids.data();
  count = static_cast<int>(ids.size());
  tets.resize(count);
  grad.resize(count);
  elastic_volume.resize(count);
  weight.resize(count);
  order.resize(count);
  weight_source = nullptr;
  for (int k = 0; k < count; ++k) {
    tets[k] = geo.tets[ids[k]];
    grad[k] = geo.grad[ids[k]];
    elastic_volume[k] = geo.elastic_volume[ids[k]];
  }
  std::iota(order.begin(), order.end(), 0);
}

void PackedTets::clear() {
  source = nullptr;
  count = 0;
  tets.clear();
  grad.clear();
  elastic_volume.clear();
  weight.clear();
  weight_source = nullptr;
  order.clear();
}

}  // namespace mrsim
