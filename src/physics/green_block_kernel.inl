// The Green–Lagrange block kernel (green_nodal_forces.hpp), included by green_nodal_forces.cpp
// (baseline x86-64) and green_nodal_forces_avx2.cpp (compiled with -mavx2). Plain arrays and
// loops only, in an anonymous namespace: no inline function of a shared header (Eigen, std::)
// is instantiated here, since the linker keeps one copy of such a function for the whole
// program and it could be the AVX2 one. Without -mfma and with ISO C++'s -ffp-contract=off,
// both compilations perform the same IEEE operations in the same order: the same bits.
// No include guard: each including file gets its own copy.

namespace {


// Eigen's order of evaluation for 3 × 3 fixed-size doubles (what green_piola() compiles to on
// x86-64): Aᵀ B sums its three terms left to right; A B and A v do so on rows 0 and 1 (SIMD
// packets) but as a0 + (a1 + a2) on row 2 (the scalar remainder); a trace is a0 + (a1 + a2).
inline double left(double a0, double a1, double a2) { return (a0 + a1) + a2; }
inline double right(double a0, double a1, double a2) { return a0 + (a1 + a2); }
inline double by_row(int i, double a0, double a1, double a2) {
  return i < 2 ? left(a0, a1, a2) : right(a0, a1, a2);
}

#define MRSIM_IX(i, j) (3 * (i) + (j))

constexpr int kDiagonal[3] = {0, 4, 8};  // the diagonal of a 3 × 3 row-major matrix

// Where value j of tet t lies in blocked packed data of n values per tet (GreenKernelData).
inline const double* blocked(const double* blocks, int n, int t) {
  return blocks + (t / kPackedBlock) * n * kPackedBlock + t % kPackedBlock;
}

// Values 0..N-1 of the block's B tets from blocked packed data: whole rows when the tets are
// consecutive within one packed block (every full block of a packed list), else tet by tet.
template <int N, int B>
void from_blocks(const double* blocks, const int* tets, double (&out)[N][B]) {
  const int t0 = tets[0];
  if (tets[B - 1] - t0 == B - 1 && t0 % kPackedBlock + B <= kPackedBlock) {
    const double* s = blocked(blocks, N, t0);
    for (int j = 0; j < N; ++j)
      for (int b = 0; b < B; ++b) out[j][b] = s[j * kPackedBlock + b];
    return;
  }
  for (int b = 0; b < B; ++b) {
    const double* s = blocked(blocks, N, tets[b]);
    for (int j = 0; j < N; ++j) out[j][b] = s[j * kPackedBlock];
  }
}

// The block's shape gradients ∇N_a (component k of vertex a, per tet), gathered once.
template <int B>
void shape_gradients(const GreenKernelData& m, const int* tets, double (&g)[4][3][B]) {
  if (m.grad_blocks) {
    from_blocks<12, B>(m.grad_blocks, tets, reinterpret_cast<double(&)[12][B]>(g));
    return;
  }
  for (int b = 0; b < B; ++b) {
    const double(&grad)[4][3] = m.grad[tets[b]];
    for (int a = 0; a < 4; ++a)
      for (int k = 0; k < 3; ++k) g[a][k][b] = grad[a][k];
  }
}

// G = Σ_a x_{v_a} ∇N_aᵀ (tet_gradient), for each tet of the block, from the vertices' values
// gathered across the tets. Inlined where X is a local array: out of line, GCC could not rule
// out that G aliases X and compiled it 2.5 times longer.
template <int B>
[[gnu::always_inline]] inline void gradient_products(const double (&X)[4][3][B],
                                                     const double (&g)[4][3][B],
                                                     double (&G)[9][B]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int b = 0; b < B; ++b) {
        double s = X[0][i][b] * g[0][j][b];
        s += X[1][i][b] * g[1][j][b];
        s += X[2][i][b] * g[2][j][b];
        s += X[3][i][b] * g[3][j][b];
        G[MRSIM_IX(i, j)][b] = s;
      }
}

// The gradients of u (G) and, damped, of v (Gd): both vertex gathers share each tet's vertex
// ids and addresses (the gathers were a fifth of the adaptive liver_probe's instructions).
template <int B, bool Damped>
void gradients(const GreenKernelData& m, const int* tets, const double (*u)[3],
               const double (*v)[3], const double (&g)[4][3][B], double (&G)[9][B],
               double (&Gd)[9][B]) {
  double X[4][3][B], Xd[Damped ? 4 : 1][3][B];
  for (int b = 0; b < B; ++b) {
    const int(&t)[4] = m.tets[tets[b]];
    for (int a = 0; a < 4; ++a) {
      const double(&ua)[3] = u[t[a]];
      for (int i = 0; i < 3; ++i) X[a][i][b] = ua[i];
      if constexpr (Damped) {
        const double(&va)[3] = v[t[a]];
        for (int i = 0; i < 3; ++i) Xd[a][i][b] = va[i];
      }
    }
  }
  gradient_products<B>(X, g, G);
  if constexpr (Damped) gradient_products<B>(Xd, g, Gd);
}

// Where a block's nodal forces go: stored per tet (the pass of a per-point gather) ...
struct StoreSink {
  static constexpr int kBlock = 8;  // tets a block
  double (*out)[4][3];
  template <int B>
  void put(const GreenKernelData&, const int* tets, const double (&f)[4][3][B]) const {
    for (int b = 0; b < B; ++b) {
      double(&out_b)[4][3] = out[tets[b]];
      for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 3; ++i) out_b[a][i] = f[a][i][b];
    }
  }
};

// ... or added at once to the points' forces, tet after tet. Over an ascending tet list each
// point receives its terms in ascending tet order, the order of its incidence list: the sums
// of the per-point gather, bit for bit (weight: skips the tets of weight zero and scales the
// others, as the weighted gather does; mask: only points whose byte is set; and only the
// points of [first, last), one thread's share).
struct ScatterSink {
  // Sixteen tets a block: bench_internal_force green, one thread, AVX2 build, paired runs:
  // 40.6–42.0 M tet-updates/s undamped (8 a block: 32.0–33.2), 26.7–27.3 damped (24.7–25.7).
  static constexpr int kBlock = 16;
  const double* weight;
  const unsigned char* mask;
  double (*f)[3];
  int first, last;  // the points [first, last) only
  template <int B>
  void put(const GreenKernelData& m, const int* tets, const double (&fv)[4][3][B]) const {
    for (int b = 0; b < B; ++b) {
      const double w = weight ? weight[tets[b]] : 1.0;
      if (w == 0) continue;
      const int(&t)[4] = m.tets[tets[b]];
      for (int a = 0; a < 4; ++a) {
        if (t[a] < first || t[a] >= last || (mask && !mask[t[a]])) continue;
        double(&fp)[3] = f[t[a]];
        if (weight)
          for (int i = 0; i < 3; ++i) fp[i] += w * fv[a][i][b];
        else
          for (int i = 0; i < 3; ++i) fp[i] += fv[a][i][b];
      }
    }
  }
};

// The nodal forces f[a][i][b] = -V (F S) ∇N_a of the block's B tets; PerTet: each tet's own
// scales (GreenKernelData::tet_scales), applied as kernel_data() applies a level's.
template <int B, bool Damped, bool PerTet>
void block_forces(const GreenKernelData& m, const int* tets, const double (*u)[3],
                  const double (*v)[3], double (&f)[4][3][B]) {
  const double lambda = m.lambda, phi = m.phi;
  const double* two_mu = m.two_mu;  // per strain component (a calibrated level's scales)
  const double* two_psi = m.two_psi;
  double g[4][3][B], G[9][B], Gd[9][B], F[9][B], S[9][B], P[9][B];
  shape_gradients<B>(m, tets, g);
  gradients<B, Damped>(m, tets, u, v, g, G, Gd);
  // E = ½ (G + Gᵀ + GᵀG); S = λ tr(E) I + 2μ E; F = I + G. E is computed once for (i, j) and
  // (j, i): IEEE sums and products commute, so green_piola()'s E(j, i) is the same bits.
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      for (int b = 0; b < B; ++b) {
        const double gtg =
            left(G[MRSIM_IX(0, i)][b] * G[MRSIM_IX(0, j)][b],
                 G[MRSIM_IX(1, i)][b] * G[MRSIM_IX(1, j)][b],
                 G[MRSIM_IX(2, i)][b] * G[MRSIM_IX(2, j)][b]);
        const double e = 0.5 * ((G[MRSIM_IX(i, j)][b] + G[MRSIM_IX(j, i)][b]) + gtg);
        S[MRSIM_IX(i, j)][b] = e;
        S[MRSIM_IX(j, i)][b] = e;
      }
  // PerTet: each tet's scales gathered first, so that the products below run across the block
  // like the level's (tet by tet, calibrated blocks took 10.1 % of the adaptive liver_probe's
  // CPU, 8.6 % across the block).
  double scales[PerTet ? 10 : 1][B];
  if constexpr (PerTet) {
    if (m.scale_blocks)
      from_blocks<10, B>(m.scale_blocks, tets, scales);
    else
      for (int b = 0; b < B; ++b)
        for (int k = 0; k < 10; ++k) scales[k][b] = m.tet_scales[tets[b]][k];
    double tr[B];
    for (int b = 0; b < B; ++b) tr[b] = right(S[0][b], S[4][b], S[8][b]);  // still E here
    for (int k = 0; k < 9; ++k)
      for (int b = 0; b < B; ++b) S[k][b] = (2.0 * (m.base[1] * scales[1 + k][b])) * S[k][b];
    for (int k : kDiagonal)
      for (int b = 0; b < B; ++b) S[k][b] += (m.base[0] * scales[0][b]) * tr[b];
  } else {
    for (int b = 0; b < B; ++b) {
      const double tr = right(S[0][b], S[4][b], S[8][b]);  // still E here
      for (int k = 0; k < 9; ++k) S[k][b] = two_mu[k] * S[k][b];
      for (int k : kDiagonal) S[k][b] += lambda * tr;
    }
  }
  for (int k = 0; k < 9; ++k)
    for (int b = 0; b < B; ++b) F[k][b] = G[k][b];
  for (int k : kDiagonal)
    for (int b = 0; b < B; ++b) F[k][b] = 1.0 + F[k][b];
  if constexpr (Damped) {
    // Ė = ½ (FᵀĠ + ĠᵀF); S += φ tr(Ė) I + 2ψ Ė.
    double D[9][B];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int b = 0; b < B; ++b)
          D[MRSIM_IX(i, j)][b] = left(F[MRSIM_IX(0, i)][b] * Gd[MRSIM_IX(0, j)][b],
                                      F[MRSIM_IX(1, i)][b] * Gd[MRSIM_IX(1, j)][b],
                                      F[MRSIM_IX(2, i)][b] * Gd[MRSIM_IX(2, j)][b]);
    if constexpr (PerTet) {
      double Ed[9][B], tr[B];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          for (int b = 0; b < B; ++b)
            Ed[MRSIM_IX(i, j)][b] = 0.5 * (D[MRSIM_IX(i, j)][b] + D[MRSIM_IX(j, i)][b]);
      for (int b = 0; b < B; ++b) tr[b] = right(Ed[0][b], Ed[4][b], Ed[8][b]);
      for (int k = 0; k < 9; ++k)
        for (int b = 0; b < B; ++b) Ed[k][b] = (2.0 * (m.base[3] * scales[1 + k][b])) * Ed[k][b];
      for (int k : kDiagonal)
        for (int b = 0; b < B; ++b) Ed[k][b] += (m.base[2] * scales[0][b]) * tr[b];
      for (int k = 0; k < 9; ++k)
        for (int b = 0; b < B; ++b) S[k][b] += Ed[k][b];
    } else {
      for (int b = 0; b < B; ++b) {
        double Ed[9];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            Ed[MRSIM_IX(i, j)] = 0.5 * (D[MRSIM_IX(i, j)][b] + D[MRSIM_IX(j, i)][b]);
        const double tr = right(Ed[0], Ed[4], Ed[8]);
        double V[9];
        for (int k = 0; k < 9; ++k) V[k] = two_psi[k] * Ed[k];
        for (int k : kDiagonal) V[k] += phi * tr;
        for (int k = 0; k < 9; ++k) S[k][b] += V[k];
      }
    }
  }
  // P = -V F S, then the nodal forces P ∇N_a.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int b = 0; b < B; ++b)
        P[MRSIM_IX(i, j)][b] = by_row(i, F[MRSIM_IX(i, 0)][b] * S[MRSIM_IX(0, j)][b],
                                      F[MRSIM_IX(i, 1)][b] * S[MRSIM_IX(1, j)][b],
                                      F[MRSIM_IX(i, 2)][b] * S[MRSIM_IX(2, j)][b]);
  for (int b = 0; b < B; ++b) {
    const double scale = -m.volume[tets[b]];
    for (int k = 0; k < 9; ++k) P[k][b] *= scale;
  }
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i)
      for (int b = 0; b < B; ++b)
        f[a][i][b] = by_row(i, P[MRSIM_IX(i, 0)][b] * g[a][0][b], P[MRSIM_IX(i, 1)][b] * g[a][1][b],
                            P[MRSIM_IX(i, 2)][b] * g[a][2][b]);
}

template <int B, bool Damped, bool PerTet, class Sink>
void block(const GreenKernelData& m, const int* tets, const double (*u)[3], const double (*v)[3],
           const Sink& sink) {
  double f[4][3][B];
  block_forces<B, Damped, PerTet>(m, tets, u, v, f);
  sink.template put<B>(m, tets, f);
}

// The last 1-3 tets of a list: one block of four whose missing tets repeat the last one, each
// real tet's forces handed to the sink alone. Each tet's arithmetic does not depend on its block
// (the same bits). There is no single-tet block: GCC 12 compiles block_forces<1> for AVX-512
// (-O3, with both its loop and SLP vectorizers) into wrong forces on two components of one
// vertex (GreenNodalForces.BitIdenticalToGreenPiola caught it).
template <bool Damped, bool PerTet, class Sink>
void tail(const GreenKernelData& m, const int* tets, int count, const double (*u)[3],
          const double (*v)[3], const Sink& sink) {
  int padded[4];
  for (int b = 0; b < 4; ++b) padded[b] = tets[b < count ? b : count - 1];
  double f[4][3][4];
  block_forces<4, Damped, PerTet>(m, padded, u, v, f);
  for (int b = 0; b < count; ++b) {
    double one[4][3][1];
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) one[a][i][0] = f[a][i][b];
    sink.template put<1>(m, tets + b, one);
  }
}

#undef MRSIM_IX

// The shape gradients of the next block's tets (96 bytes, two cache lines each) asked for while
// this block computes: the largest stream the kernel reads per tet. A hint only: the same bits.
// bench_internal_force, one thread, fastest call, alternating with the binary before: on a
// busy host damped 27.2–28.1 -> 30.6–32.4 M tet-updates/s; on a quiet one the gain shrinks to
// 1–5 % (undamped 42.0–42.6 -> 42.5–42.9, damped 30.1–32.2 -> 31.8–32.4). Prefetching the
// tets' vertex ids and volumes too was no faster.
template <int B>
inline void prefetch_gradients(const GreenKernelData& m, const int* tets) {
  for (int b = 0; b < B; ++b) {
    const char* g = reinterpret_cast<const char*>(m.grad[tets[b]]);
    __builtin_prefetch(g);
    __builtin_prefetch(g + sizeof(m.grad[0]) - 1);
    asm volatile("");  // not vectorized: GCC drops the prefetches of a loop it vectorizes
  }
}

template <bool Damped, bool PerTet, class Sink>
void all_blocks(const GreenKernelData& m, const int* tets, int count, const double (*u)[3],
                const double (*v)[3], const Sink& sink) {
  constexpr int kBlock = Sink::kBlock;
  int k = 0;
  for (; k + kBlock <= count; k += kBlock) {
    // Blocked packed data is read in order, as the processor's own prefetch expects.
    if (!m.grad_blocks && k + 2 * kBlock <= count)
      prefetch_gradients<kBlock>(m, tets + k + kBlock);
    block<kBlock, Damped, PerTet>(m, tets + k, u, v, sink);
  }
  if constexpr (kBlock > 8)
    for (; k + 8 <= count; k += 8) block<8, Damped, PerTet>(m, tets + k, u, v, sink);
  // The tail in fours, then the last 1-3 in one padded block of four: each level's live tets
  // end in up to 15 (single-tet blocks were 1.7 % of the adaptive liver_probe's instructions).
  for (; k + 4 <= count; k += 4) block<4, Damped, PerTet>(m, tets + k, u, v, sink);
  if (k < count) tail<Damped, PerTet>(m, tets + k, count - k, u, v, sink);
}

// The whole pass, damped (φ or ψ non-zero, MaterialLaw::damped()) or not, with per-tet scales or
// not: what each build exports.
template <class Sink>
void every_block(const GreenKernelData& m, const int* tets, int count, const double (*u)[3],
                 const double (*v)[3], const Sink& sink) {
  const bool damped = m.phi != 0 || m.two_psi[0] != 0;  // scales are positive: ψ ≠ 0 ⇔ two_psi ≠ 0
  if (m.tet_scales)
    damped ? all_blocks<true, true>(m, tets, count, u, v, sink)
           : all_blocks<false, true>(m, tets, count, u, v, sink);
  else
    damped ? all_blocks<true, false>(m, tets, count, u, v, sink)
           : all_blocks<false, false>(m, tets, count, u, v, sink);
}

}  // namespace
