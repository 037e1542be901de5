#include "physics/green_nodal_forces.hpp"

#include <atomic>
#include <stdexcept>

#include "physics/green_kernel_data.hpp"

namespace mrsim {

#include "physics/green_block_kernel.inl"

namespace {

static_assert(sizeof(StiffnessScales) == 10 * sizeof(double));

// The kernel's view of tet arrays (the level's own or a packed copy) with the level's material
// and, with per_tet, each tet's scales (`scales` empty: none).
GreenKernelData kernel_data(const MaterialLaw& law, const Tet* tets, const TetGradients* grad,
                            const double* volume, const std::vector<StiffnessScales>& scales) {
  GreenKernelData d{reinterpret_cast<const double(*)[4][3]>(grad),
                    reinterpret_cast<const int(*)[4]>(tets),
                    volume,
                    law.lambda * law.scales.lambda,
                    law.phi * law.scales.lambda,
                    {},
                    {}};
  // 2 (μ s) is 2μ exactly when s = 1: an isotropic level keeps its bits.
  for (int k = 0; k < 9; ++k) {
    d.two_mu[k] = 2.0 * (law.mu * law.scales.mu[k]);
    d.two_psi[k] = 2.0 * (law.psi * law.scales.mu[k]);
  }
  if (!scales.empty()) {
    d.tet_scales = reinterpret_cast<const double(*)[10]>(scales.data());
    d.base[0] = law.lambda, d.base[1] = law.mu, d.base[2] = law.phi, d.base[3] = law.psi;
  }
  return d;
}

static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(TetGradients) == 12 * sizeof(double) &&
              sizeof(Tet) == 4 * sizeof(int));

}  // namespace

GreenKernelData green_kernel_data(const LevelModel& m) {
  return kernel_data(m.law, m.geo.tets.data(), m.geo.grad.data(), m.geo.volume.data(),
                     m.geo.scales);
}

bool has_avx512_kernel() {
#if defined(MRSIM_AVX512_KERNEL)
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
         __builtin_cpu_supports("avx512dq");
#else
  return false;
#endif
}

namespace {

// The builds of the kernel, all with the same bits (GreenNodalForces.BitIdenticalToGreenPiola
// runs each). AVX-512 gave 41-43 M tet-updates/s against AVX2's 33 on a Sapphire Rapids Xeon
// (bench_internal_force green/1).
enum class KernelBuild { Baseline, Avx2, Avx512 };

constexpr const char* kBuildNames[] = {"baseline", "avx2", "avx512"};
constexpr KernelBuild kWidestFirst[] = {KernelBuild::Avx512, KernelBuild::Avx2,
                                        KernelBuild::Baseline};

bool runs(KernelBuild b) {
  switch (b) {
    case KernelBuild::Avx512: return has_avx512_kernel();  // false without the AVX-512 file
#if defined(MRSIM_AVX2_KERNEL)
    case KernelBuild::Avx2: return __builtin_cpu_supports("avx2");
#endif
    case KernelBuild::Baseline: return true;
    default: return false;
  }
}

// The widest build the processor runs, found once (thread-safe: a static's initialisation).
KernelBuild widest_build() {
  static const KernelBuild build = [] {
    for (const KernelBuild b : kWidestFirst)
      if (runs(b)) return b;
    return KernelBuild::Baseline;
  }();
  return build;
}

// choose_green_kernel()'s build, or -1 for the widest.
std::atomic<int> chosen{-1};

KernelBuild kernel_build() {
  const int c = chosen.load(std::memory_order_relaxed);
  return c < 0 ? widest_build() : static_cast<KernelBuild>(c);
}

}  // namespace

const char* green_kernel_name() { return kBuildNames[static_cast<int>(kernel_build())]; }

bool green_kernel_is_wide() { return kernel_build() != KernelBuild::Baseline; }

std::vector<std::string> green_kernel_builds() {
  std::vector<std::string> names;
  for (const KernelBuild b : kWidestFirst)
    if (runs(b)) names.emplace_back(kBuildNames[static_cast<int>(b)]);
  return names;
}

std::string green_kernel_build_list() {
  std::string list;
  for (const std::string& n : green_kernel_builds()) list += (list.empty() ? "" : ", ") + n;
  return list;
}

void choose_green_kernel(std::string_view name) {
  for (const KernelBuild b : kWidestFirst)
    if (name == kBuildNames[static_cast<int>(b)] && runs(b)) {
      chosen.store(static_cast<int>(b), std::memory_order_relaxed);
      return;
    }
  throw std::invalid_argument("the force kernel build '" + std::string(name) +
                              "' is not one this processor runs (" + green_kernel_build_list() +
                              ")");
}

void green_nodal_forces(const LevelModel& m, const int* tets, int count, const Vec3* u,
                        const Vec3* v, TetGradients* out) {
  const GreenKernelData d = green_kernel_data(m);
  const auto* u3 = reinterpret_cast<const double(*)[3]>(u);
  const auto* v3 = reinterpret_cast<const double(*)[3]>(v);
  auto* out3 = reinterpret_cast<double(*)[4][3]>(out);
  switch (kernel_build()) {
#if defined(MRSIM_AVX512_KERNEL)
    case KernelBuild::Avx512: return green_nodal_forces_avx512(d, tets, count, u3, v3, out3);
#endif
#if defined(MRSIM_AVX2_KERNEL)
    case KernelBuild::Avx2: return green_nodal_forces_avx2(d, tets, count, u3, v3, out3);
#endif
    default: return green_nodal_forces_baseline(d, tets, count, u3, v3, out3);
  }
}

void green_nodal_forces_baseline(const GreenKernelData& d, const int* tets, int count,
                                 const double (*u)[3], const double (*v)[3],
                                 double (*out)[4][3]) {
  every_block(d, tets, count, u, v, StoreSink{out});
}

namespace {

void scatter(const GreenKernelData& d, const int* tets, int count, const Vec3* u, const Vec3* v,
             const double* weight, const unsigned char* mask, Vec3* f, int first, int last) {
  const auto* u3 = reinterpret_cast<const double(*)[3]>(u);
  const auto* v3 = reinterpret_cast<const double(*)[3]>(v);
  const GreenScatterTarget target{weight, mask, reinterpret_cast<double(*)[3]>(f), first, last};
  switch (kernel_build()) {
#if defined(MRSIM_AVX512_KERNEL)
    case KernelBuild::Avx512: return green_scatter_forces_avx512(d, tets, count, u3, v3, target);
#endif
#if defined(MRSIM_AVX2_KERNEL)
    case KernelBuild::Avx2: return green_scatter_forces_avx2(d, tets, count, u3, v3, target);
#endif
    default: return green_scatter_forces_baseline(d, tets, count, u3, v3, target);
  }
}

}  // namespace

void green_scatter_forces(const LevelModel& m, const int* tets, int count, const Vec3* u,
                          const Vec3* v, const double* weight, const unsigned char* mask,
                          Vec3* f, int first, int last) {
  scatter(green_kernel_data(m), tets, count, u, v, weight, mask, f, first, last);
}

void green_scatter_packed(const LevelModel& m, PackedTets& packed, const Vec3* u, const Vec3* v,
                          const double* weight, const unsigned char* mask, Vec3* f) {
  const int n = packed.count;
  if (weight && weight != packed.weight_source) {
    for (int k = 0; k < n; ++k) packed.weight[k] = weight[packed.source[k]];
    packed.weight_source = weight;
  }
  GreenKernelData d =
      kernel_data(m.law, packed.tets.data(), packed.grad.data(), packed.volume.data(), packed.scales);
  d.grad_blocks = packed.grad_blocks.data();
  if (!packed.scale_blocks.empty()) d.scale_blocks = packed.scale_blocks.data();
  scatter(d, packed.order.data(), n, u, v, weight ? packed.weight.data() : nullptr, mask, f, 0,
          kAllPoints);
}

void green_scatter_forces_baseline(const GreenKernelData& d, const int* tets, int count,
                                   const double (*u)[3], const double (*v)[3],
                                   const GreenScatterTarget& target) {
  every_block(d, tets, count, u, v, ScatterSink{target.weight, target.mask, target.f, target.first, target.last});
}

}  // namespace mrsim
