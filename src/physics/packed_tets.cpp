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
  const int blocks = (count + kPackedBlock - 1) / kPackedBlock;
  grad_blocks.assign(static_cast<std::size_t>(blocks) * 12 * kPackedBlock, 0.0);
  scale_blocks.assign(scales.empty() ? 0 : static_cast<std::size_t>(blocks) * 10 * kPackedBlock,
                      0.0);
  for (int k = 0; k < count; ++k) {
    double* g = grad_blocks.data() + (k / kPackedBlock) * 12 * kPackedBlock + k % kPackedBlock;
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) g[(3 * a + i) * kPackedBlock] = grad[k][a][i];
    if (scales.empty()) continue;
    double* s = scale_blocks.data() + (k / kPackedBlock) * 10 * kPackedBlock + k % kPackedBlock;
    s[0] = scales[k].lambda;
    for (int j = 0; j < 9; ++j) s[(1 + j) * kPackedBlock] = scales[k].mu[j];
  }
}

void PackedTets::clear() {
  source = nullptr;
  count = 0;
  tets.clear();
  grad.clear();
  volume.clear();
  scales.clear();
  grad_blocks.clear();
  scale_blocks.clear();
  weight.clear();
  weight_source = nullptr;
  order.clear();
  closed = false;
}

}  // namespace mrsim
