#pragma once
// The Green–Lagrange per-tet pass (method.md §2.3) for a list of tets, eight at a time: each
// stage of the stress is written as plain loops over the eight tets, which the compiler turns
// into SIMD arithmetic across tets (issue 17 point 4). Every tet's arithmetic is the one of
// green_piola() in stress.hpp, operation for operation and in the same order, so the forces
// are bit-identical to it (GreenNodalForces.BitIdenticalToGreenPiola), whatever the block a
// tet falls in and whatever the thread count. On x86-64 the AVX-512 or AVX2 build of the same
// kernel runs where the processor has it, with the same bits (green_block_kernel.inl).
#include <string>
#include <string_view>
#include <vector>

#include "physics/green_kernel_data.hpp"
#include "physics/level_model.hpp"
#include "physics/packed_tets.hpp"

namespace mrsim {

/// out[tets[k]][a] = -V P ∇N_a for k in [0, count), P = F (S + 𝒱) of green_piola(); v is read
/// only when the law is damped.
void green_nodal_forces(const LevelModel& m, const int* tets, int count, const Vec3* u,
                        const Vec3* v, TetGradients* out);

/// The same pass adding each tet's forces to its vertices at once, tets in the order given:
/// f[p] += w_t (-V P ∇N_a) for the vertex p = a of tets[k], k ascending, where mask[p] is set
/// (every vertex when mask is null) and first <= p < last, with w_t = weight[t] and tets of
/// weight zero skipped (w = 1 when weight is null). Over an ascending tet list the sums are those
/// of a per-point gather in incidence order (internal_force.cpp), bit for bit. Threads that
/// share a call's points out by disjoint ranges give the same bits.
void green_scatter_forces(const LevelModel& m, const int* tets, int count, const Vec3* u,
                          const Vec3* v, const double* weight, const unsigned char* mask,
                          Vec3* f, int first = 0, int last = kAllPoints);

/// green_scatter_forces() over the packed tets of `m` (physics/packed_tets.hpp), with the level's
/// per-tet `weight` (null: 1) gathered into the packed order at the first pass after pack() or
/// after PackedTets::weight_source was reset (the weights were edited): the same bits as over
/// their ids.
void green_scatter_packed(const LevelModel& m, PackedTets& packed, const Vec3* u, const Vec3* v,
                          const double* weight, const unsigned char* mask, Vec3* f);

/// The build of the kernel this process runs: the widest the processor has, "avx512", "avx2"
/// or "baseline", unless choose_green_kernel() chose another (every build gives the same bits).
/// summary.json and `mrsim --version` say it, since it sets the speed.
const char* green_kernel_name();
/// Is that build wider than the baseline (AVX2 or AVX-512)? The ghosts' per-step passes take
/// their AVX2 build with it (hierarchy/barycentric_rows.hpp).
bool green_kernel_is_wide();

/// The builds this processor runs, widest first; and the same as text, "avx512, avx2, baseline".
std::vector<std::string> green_kernel_builds();
std::string green_kernel_build_list();

/// Runs the build named (one of green_kernel_builds()) from now on: `MRSIM_KERNEL`, for a
/// processor that slows its clock under AVX-512, and to check that every build gives the same
/// results. Call it before any force is computed (not thread-safe against a running pass).
/// Throws std::invalid_argument naming the builds this processor runs.
void choose_green_kernel(std::string_view name);

/// The level's arrays as the kernel builds read them (green_kernel_data.hpp): the same
/// pass through green_nodal_forces_baseline(), _avx2() or _avx512() directly.
GreenKernelData green_kernel_data(const LevelModel& m);

}  // namespace mrsim
