// Built with -mavx2 -mno-fma -ffp-contract=off (src/CMakeLists.txt): run only when row_build()
// says so. No AVX constant at namespace scope: its initialisation would run on every processor.
#include <immintrin.h>

#include "hierarchy/barycentric_rows.hpp"

namespace mrsim::avx2 {

namespace {

// x, y, z of a Vec3 (24 bytes): a masked load never reads the next point's x, which past the
// array's last point may not be there.
inline __m256d load3(const Vec3& v, __m256i xyz) { return _mm256_maskload_pd(v.data(), xyz); }

inline void store3(Vec3& v, __m256d x) {
  _mm_storeu_pd(v.data(), _mm256_castpd256_pd128(x));
  _mm_store_sd(v.data() + 2, _mm256_extractf128_pd(x, 1));
}

inline __m256d combine(const Vec3* s, const std::array<int, 4>& i, const __m256d b[4],
                       __m256i xyz) {
  __m256d sum = _mm256_mul_pd(b[0], load3(s[i[0]], xyz));
  sum = _mm256_add_pd(sum, _mm256_mul_pd(b[1], load3(s[i[1]], xyz)));
  sum = _mm256_add_pd(sum, _mm256_mul_pd(b[2], load3(s[i[2]], xyz)));
  return _mm256_add_pd(sum, _mm256_mul_pd(b[3], load3(s[i[3]], xyz)));
}

}  // namespace

void interpolate_rows(std::span<const int> points, const std::array<int, 4>* source,
                      const std::array<double, 4>* bary, const Vec3* su, const Vec3* sv, Vec3* tu,
                      Vec3* tv) {
  const __m256i xyz = _mm256_setr_epi64x(-1, -1, -1, 0);
  for (int p : points) {
    const __m256d b[4] = {_mm256_broadcast_sd(&bary[p][0]), _mm256_broadcast_sd(&bary[p][1]),
                          _mm256_broadcast_sd(&bary[p][2]), _mm256_broadcast_sd(&bary[p][3])};
    store3(tu[p], combine(su, source[p], b, xyz));
    store3(tv[p], combine(sv, source[p], b, xyz));
  }
}

// x,y and z apart, as they are stored: a 32-byte load of a source that the row before has just
// written (neighbouring ghosts share sources) waits for the two stores to retire instead of
// taking their data (store-to-load forwarding needs one store to cover the load).
void scatter_rows(std::span<const int> points, const std::array<int, 4>* source,
                  const std::array<double, 4>* bary, const Vec3* from, Vec3* to) {
  for (int p : points) {
    const __m128d fxy = _mm_loadu_pd(from[p].data()), fz = _mm_load_sd(from[p].data() + 2);
    for (int k = 0; k < 4; ++k) {  // in order: two rows may share a source
      double* q = to[source[p][k]].data();
      const __m128d b = _mm_set1_pd(bary[p][k]);
      _mm_storeu_pd(q, _mm_add_pd(_mm_loadu_pd(q), _mm_mul_pd(b, fxy)));
      _mm_store_sd(q + 2, _mm_add_sd(_mm_load_sd(q + 2), _mm_mul_sd(b, fz)));
    }
  }
}

}  // namespace mrsim::avx2
