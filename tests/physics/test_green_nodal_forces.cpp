// The blocked Green–Lagrange tet pass (physics/green_nodal_forces) against the per-tet
// green_piola() it replaces in the force kernel: bit for bit, for every tet of lists of any
// length and order (full blocks of eight and remainders), damped and undamped, at small and
// large deformation, for the baseline and the AVX2 builds of the kernel. Bit-identity is what keeps every golden file and the thread-count
// independence of the results.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include "mesh/box_mesh.hpp"
#include "physics/green_nodal_forces.hpp"
#include "physics/stress.hpp"

namespace mrsim {
namespace {

TetGradients reference(const LevelModel& m, int t, const Vec3* u, const Vec3* v) {
  const TetGradients& g = m.geo.grad[t];
  const Mat3 G = tet_gradient(g, m.geo.tets[t], u);
  const Mat3 Gd = tet_gradient(g, m.geo.tets[t], v);
  Mat3 P = green_piola(G, m.law.damped() ? &Gd : nullptr, m.law);
  P *= -m.geo.volume[t];
  TetGradients out;
  for (int a = 0; a < 4; ++a) out[a].noalias() = P * g[a];
  return out;
}

using Kernel = void (*)(const GreenKernelData&, const int*, int, const double (*)[3],
                       const double (*)[3], double (*)[4][3]);

// The kernel behind green_nodal_forces(), then each build of it called directly: the baseline
// one and, where the processor has AVX2, the AVX2 one (the dispatcher picks that one here).
std::vector<std::pair<const char*, Kernel>> kernels() {
  std::vector<std::pair<const char*, Kernel>> k{{"dispatched", nullptr},
                                                {"baseline", &green_nodal_forces_baseline}};
#if defined(__x86_64__)
  if (__builtin_cpu_supports("avx2")) k.emplace_back("avx2", &green_nodal_forces_avx2);
#endif
  return k;
}

TEST(GreenNodalForces, BitIdenticalToGreenPiola) {
  TetMesh mesh = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.06, 0.04), 7, 5, 4);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.002, 0.002);
  for (Vec3& p : mesh.points) p += Vec3(jitter(rng), jitter(rng), jitter(rng));
  for (const bool damped : {false, true})
    for (const double amplitude : {1e-4, 3e-2}) {
      MaterialLaw law;
      law.strain = StrainMeasure::GreenLagrange;
      law.lambda = 5.0e5;
      law.mu = 3.0e4;
      if (damped) {
        law.phi = 0.7;
        law.psi = 20;
      }
      const LevelModel m = build_level_model(mesh, law);
      std::uniform_real_distribution<double> d(-amplitude, amplitude);
      std::vector<Vec3> u(m.num_points()), v(m.num_points());
      for (int i = 0; i < m.num_points(); ++i) {
        u[i] = Vec3(d(rng), d(rng), d(rng));
        v[i] = 10 * Vec3(d(rng), d(rng), d(rng));
      }
      // Every tet, then a shuffled list of odd length (blocks start anywhere).
      std::vector<int> all(m.num_tets());
      for (int t = 0; t < m.num_tets(); ++t) all[t] = t;
      std::vector<int> some = all;
      std::shuffle(some.begin(), some.end(), rng);
      some.resize(some.size() / 3 * 2 + 1);
      for (const auto& [name, kernel] : kernels())
        for (const std::vector<int>* list : {&all, &some}) {
          std::vector<TetGradients> out(m.num_tets());
          const int n = static_cast<int>(list->size());
          if (kernel == nullptr)
            green_nodal_forces(m, list->data(), n, u.data(), v.data(), out.data());
          else
            kernel(green_kernel_data(m), list->data(), n,
                   reinterpret_cast<const double(*)[3]>(u.data()),
                   reinterpret_cast<const double(*)[3]>(v.data()),
                   reinterpret_cast<double(*)[4][3]>(out.data()));
          for (int t : *list) {
            const TetGradients expected = reference(m, t, u.data(), v.data());
            ASSERT_EQ(std::memcmp(&expected, &out[t], sizeof(TetGradients)), 0)
                << name << " kernel, tet " << t << (damped ? " damped" : "") << " amplitude "
                << amplitude;
          }
        }
    }
}

}  // namespace
}  // namespace mrsim
