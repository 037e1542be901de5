#pragma once
// What the Green–Lagrange block kernel reads, as plain arrays (physics/green_block_kernel.inl):
// the same kernel is compiled for baseline x86-64, for AVX2 and for AVX-512, and the builds share
// no inline code (see there).

namespace mrsim {

struct GreenKernelData {
  const double (*grad)[4][3];  // ∇N_a of each tet
  const int (*tets)[4];        // vertices of each tet
  const double* volume;        // rest volume of each tet
  // λ, φ (times the level's λ scale) and 2μ, 2ψ per strain component (times the level's μ scales,
  // MaterialLaw::scales; all equal on an isotropic level).
  double lambda, phi;
  double two_mu[9], two_psi[9];
  // object.calibration: per_tet: each tet's scales {λ, μ[9]} (TetGeometry::scales), applied to
  // the law's own λ, μ, φ, ψ in `base` as kernel_data() applies a level's: null for none.
  const double (*tet_scales)[10] = nullptr;
  double base[4] = {0, 0, 0, 0};
  // A packed copy (physics/packed_tets.hpp) also holds ∇N and the per-tet scales in blocks of
  // kPackedBlock tets, component by component: value j of tet t at
  // [(t / kPackedBlock) * n * kPackedBlock + j * kPackedBlock + t % kPackedBlock], n = 12 for ∇N
  // (j = 3a + k), 10 for the scales. A block of consecutive tets then reads them as vectors
  // instead of transposing each tet's row. Null for a level's own arrays. The lists passed over
  // such data are ascending (PackedTets::order).
  const double* grad_blocks = nullptr;
  const double* scale_blocks = nullptr;
};

/// Tets per block of GreenKernelData::grad_blocks and scale_blocks: the kernel's widest block.
inline constexpr int kPackedBlock = 16;

/// No upper bound on the points a scattering pass writes (one thread owns them all).
inline constexpr int kAllPoints = 1 << 30;

/// Where the scattering form of the pass adds its forces (green_scatter_forces()).
struct GreenScatterTarget {
  const double* weight;        // per tet, or null for 1 (tets of weight zero are skipped)
  const unsigned char* mask;   // per point, or null for every point
  double (*f)[3];              // per point
  int first = 0, last = kAllPoints;  // only the points [first, last) are written
};

/// out[tets[k]][a] = -V P ∇N_a for k in [0, count): the baseline build of the kernel.
void green_nodal_forces_baseline(const GreenKernelData& d, const int* tets, int count,
                                 const double (*u)[3], const double (*v)[3], double (*out)[4][3]);
/// The same kernel compiled with -mavx2 (x86-64 builds only; the caller checks the processor).
void green_nodal_forces_avx2(const GreenKernelData& d, const int* tets, int count,
                             const double (*u)[3], const double (*v)[3], double (*out)[4][3]);
/// The same kernel adding each block's forces to the points at once, each build.
void green_scatter_forces_baseline(const GreenKernelData& d, const int* tets, int count,
                                   const double (*u)[3], const double (*v)[3],
                                   const GreenScatterTarget& target);
void green_scatter_forces_avx2(const GreenKernelData& d, const int* tets, int count,
                               const double (*u)[3], const double (*v)[3],
                               const GreenScatterTarget& target);
/// The same kernel compiled for AVX-512 F/VL/DQ (x86-64 builds only; the caller checks the
/// processor: has_avx512_kernel()).
void green_nodal_forces_avx512(const GreenKernelData& d, const int* tets, int count,
                               const double (*u)[3], const double (*v)[3], double (*out)[4][3]);
void green_scatter_forces_avx512(const GreenKernelData& d, const int* tets, int count,
                                 const double (*u)[3], const double (*v)[3],
                                 const GreenScatterTarget& target);

/// Whether this build has the AVX-512 kernel (the compiler took its flags) and this processor (and
/// its operating system) runs it: F, VL and DQ. Defined
/// out of line in the baseline build (green_nodal_forces.cpp): an inline function here would be
/// compiled into the AVX-512 file too, and the linker could keep that copy.
bool has_avx512_kernel();

}  // namespace mrsim
