// The Green–Lagrange block kernel built for AVX-512 (src/CMakeLists.txt, x86-64 only): the
// sixteen tets of a block go through two 8-wide instead of four 4-wide operations per stage.
// The processor has FMA here, but ISO C++'s -ffp-contract=off (and the flag given again for this
// file) keeps every product and sum a separate IEEE operation in the kernel's order: the same
// bits as the baseline build (green_block_kernel.inl).
#include "physics/green_kernel_data.hpp"

namespace mrsim {

#include "physics/green_block_kernel.inl"

void green_nodal_forces_avx512(const GreenKernelData& d, const int* tets, int count,
                               const double (*u)[3], const double (*v)[3],
                               double (*out)[4][3]) {
  every_block(d, tets, count, u, v, StoreSink{out});
}

void green_scatter_forces_avx512(const GreenKernelData& d, const int* tets, int count,
                                 const double (*u)[3], const double (*v)[3],
                                 const GreenScatterTarget& target) {
  every_block(d, tets, count, u, v,
              ScatterSink{target.weight, target.mask, target.f, target.first, target.last});
}

}  // namespace mrsim
