// The Green–Lagrange block kernel built with -mavx2 (src/CMakeLists.txt, x86-64 only): the eight
// tets of a block go through 4-wide instead of 2-wide SIMD arithmetic. No FMA: the same bits as
// the baseline build (green_block_kernel.inl).
#include "physics/green_kernel_data.hpp"

namespace mrsim {

#include "physics/green_block_kernel.inl"

void green_nodal_forces_avx2(const GreenKernelData& d, const int* tets, int count,
                             const double (*u)[3], const double (*v)[3], double (*out)[4][3]) {
  every_block(d, tets, count, u, v, StoreSink{out});
}

void green_scatter_forces_avx2(const GreenKernelData& d, const int* tets, int count,
                               const double (*u)[3], const double (*v)[3],
                               const GreenScatterTarget& target) {
  every_block(d, tets, count, u, v, ScatterSink{target.weight, target.mask, target.f, target.first, target.last});
}

}  // namespace mrsim
