#pragma once
// The two per-step passes of the ghosts (method.md §4.8), over one list of points each with
// four sources and their barycentric weights (Embedding::source, Embedding::bary):
//   interpolate: target[p] = b₀ s[i₀] + b₁ s[i₁] + b₂ s[i₂] + b₃ s[i₃], displacement and velocity;
//   scatter:     to[i_k] += b_k from[p], k = 0..3 (the transpose: the ghosts' forces).
// Built twice, with the same bits: baseline x86-64 (GCC pairs x,y in SSE2 and does z alone) and
// AVX2 (barycentric_rows_avx2.cpp: the interpolation holds x,y,z in one register, the scatter
// x,y and z apart as they are stored; no FMA contraction, the same products and sums in the
// same order). The AVX2 build runs where the force kernel runs a wide build (MRSIM_KERNEL):
// ~100 instructions per ghost and step were 7 % of liver_probe's adaptive run (issue 17).
#include <array>
#include <span>

#include "core/vec.hpp"

namespace mrsim {

enum class RowBuild { Baseline, Avx2 };

/// Avx2 when it was compiled in and the force kernel runs a wide build (green_kernel_is_wide(),
/// physics/green_nodal_forces.hpp: the processor has AVX2); Baseline otherwise.
RowBuild row_build();

void interpolate_rows(RowBuild build, std::span<const int> points,
                      const std::array<int, 4>* source, const std::array<double, 4>* bary,
                      const Vec3* su, const Vec3* sv, Vec3* tu, Vec3* tv);

void scatter_rows(RowBuild build, std::span<const int> points, const std::array<int, 4>* source,
                  const std::array<double, 4>* bary, const Vec3* from, Vec3* to);

namespace avx2 {  // hierarchy/barycentric_rows_avx2.cpp; call through the functions above
void interpolate_rows(std::span<const int> points, const std::array<int, 4>* source,
                      const std::array<double, 4>* bary, const Vec3* su, const Vec3* sv, Vec3* tu,
                      Vec3* tv);
void scatter_rows(std::span<const int> points, const std::array<int, 4>* source,
                  const std::array<double, 4>* bary, const Vec3* from, Vec3* to);
}  // namespace avx2

}  // namespace mrsim
