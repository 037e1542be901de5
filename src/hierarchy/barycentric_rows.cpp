#include "hierarchy/barycentric_rows.hpp"

#include "physics/green_nodal_forces.hpp"

namespace mrsim {

namespace {

// Left to right, as the AVX2 build sums: ((b₀s₀ + b₁s₁) + b₂s₂) + b₃s₃.
inline Vec3 combine(const Vec3* s, const std::array<int, 4>& i, const std::array<double, 4>& b) {
  return b[0] * s[i[0]] + b[1] * s[i[1]] + b[2] * s[i[2]] + b[3] * s[i[3]];
}

}  // namespace

RowBuild row_build() {
#if defined(MRSIM_AVX2_ROWS)
  if (green_kernel_is_wide()) return RowBuild::Avx2;
#endif
  return RowBuild::Baseline;
}

void interpolate_rows(RowBuild build, std::span<const int> points,
                      const std::array<int, 4>* source, const std::array<double, 4>* bary,
                      const Vec3* su, const Vec3* sv, Vec3* tu, Vec3* tv) {
#if defined(MRSIM_AVX2_ROWS)
  if (build == RowBuild::Avx2) return avx2::interpolate_rows(points, source, bary, su, sv, tu, tv);
#else
  (void)build;
#endif
  for (int p : points) {
    tu[p] = combine(su, source[p], bary[p]);
    tv[p] = combine(sv, source[p], bary[p]);
  }
}

void scatter_rows(RowBuild build, std::span<const int> points, const std::array<int, 4>* source,
                  const std::array<double, 4>* bary, const Vec3* from, Vec3* to) {
#if defined(MRSIM_AVX2_ROWS)
  if (build == RowBuild::Avx2) return avx2::scatter_rows(points, source, bary, from, to);
#else
  (void)build;
#endif
  for (int p : points)
    for (int k = 0; k < 4; ++k) to[source[p][k]] += bary[p][k] * from[p];
}

}  // namespace mrsim
