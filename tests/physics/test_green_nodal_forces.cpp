// The blocked Green–Lagrange tet pass (physics/green_nodal_forces) against the per-tet
// green_piola() it replaces in the force kernel: bit for bit, for every tet of lists of any
// length and order (full blocks of eight and remainders), damped and undamped, at small and
// large deformation, for the baseline, AVX2 and AVX-512 builds of the kernel; and its scattering form
// (one thread) against the per-point gather of those per-tet forces. Bit-identity is what keeps
// every golden file and the thread-count independence of the results.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
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
  Mat3 P = green_piola(G, m.law.damped() ? &Gd : nullptr, m.law, m.geo.scales_of(t, m.law.scales));
  P *= -m.geo.volume[t];
  TetGradients out;
  for (int a = 0; a < 4; ++a) out[a].noalias() = P * g[a];
  return out;
}

// object.calibration: per_tet's tensors on `law` (random factors about a calibrated level's), or
// none: the kernel's per-tet form against green_piola() with each tet's scales.
void set_tet_tensors(MaterialLaw& law, bool per_tet, int tets, std::mt19937& rng) {
  law.scales = per_tet ? StiffnessScales::from_components({0.7, 1.3, 0.4, 2.1, 0.9, 1.6, 0.5})
                       : StiffnessScales{};
  law.tet_tensors = nullptr;
  if (!per_tet) return;
  std::uniform_real_distribution<double> d(0.3, 3.0);
  TetTensors q(tets);
  for (auto& t : q)
    for (double& x : t) x = d(rng);
  law.tet_tensors = std::make_shared<const TetTensors>(std::move(q));
}

using Kernel = void (*)(const GreenKernelData&, const int*, int, const double (*)[3],
                       const double (*)[3], double (*)[4][3]);

// The kernel behind green_nodal_forces(), then each build of it called directly: the baseline
// one and, where the processor has them, the AVX2 and AVX-512 ones (the dispatcher picks the
// widest).
std::vector<std::pair<const char*, Kernel>> kernels() {
  std::vector<std::pair<const char*, Kernel>> k{{"dispatched", nullptr},
                                                {"baseline", &green_nodal_forces_baseline}};
#if defined(__x86_64__)
  if (__builtin_cpu_supports("avx2")) k.emplace_back("avx2", &green_nodal_forces_avx2);
  if (has_avx512_kernel()) k.emplace_back("avx512", &green_nodal_forces_avx512);
#endif
  return k;
}

TEST(GreenNodalForces, BitIdenticalToGreenPiola) {
  TetMesh mesh = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.06, 0.04), 7, 5, 4);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.002, 0.002);
  for (Vec3& p : mesh.points) p += Vec3(jitter(rng), jitter(rng), jitter(rng));
  for (const bool per_tet : {false, true})
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
      set_tet_tensors(law, per_tet, static_cast<int>(mesh.tets.size()), rng);
      const LevelModel m = build_level_model(mesh, law);
      std::uniform_real_distribution<double> d(-amplitude, amplitude);
      std::vector<Vec3> u(m.num_points()), v(m.num_points());
      for (int i = 0; i < m.num_points(); ++i) {
        u[i] = Vec3(d(rng), d(rng), d(rng));
        v[i] = 10 * Vec3(d(rng), d(rng), d(rng));
      }
      // Every tet, then a shuffled list of odd length (blocks start anywhere), then short ones
      // ending in every kind of tail (the last 1-3 tets go through a padded block of four).
      std::vector<int> all(m.num_tets());
      for (int t = 0; t < m.num_tets(); ++t) all[t] = t;
      std::vector<int> some = all;
      std::shuffle(some.begin(), some.end(), rng);
      some.resize(some.size() / 3 * 2 + 1);
      std::vector<std::vector<int>> lists{all, some};
      for (const int n : {1, 2, 3, 7, 14, 31})
        lists.emplace_back(some.begin() + n, some.begin() + 2 * n);
      for (const auto& [name, kernel] : kernels())
        for (const std::vector<int>* list = lists.data(); list != lists.data() + lists.size();
             ++list) {
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
                << amplitude << (per_tet ? " per-tet tensors" : "");
          }
        }
    }
}

// The name summary.json and --version give is the build the dispatcher runs: the widest one.
TEST(GreenKernelName, IsTheWidestBuildThisProcessorRuns) {
  std::string expected = "baseline";
#if defined(__x86_64__)
  if (has_avx512_kernel())
    expected = "avx512";
  else if (__builtin_cpu_supports("avx2"))
    expected = "avx2";
#endif
  EXPECT_EQ(green_kernel_name(), expected);
}

// MRSIM_KERNEL's choice: each build this processor runs can be chosen and is then the one
// named; any other name is refused, naming the builds; the widest comes first.
TEST(GreenKernelName, ChoosesAnyBuildThisProcessorRunsAndRefusesOthers) {
  const std::vector<std::string> builds = green_kernel_builds();
  ASSERT_FALSE(builds.empty());
  EXPECT_EQ(builds.front(), green_kernel_name());
  EXPECT_EQ(builds.back(), "baseline");
  for (const std::string& b : builds) {
    choose_green_kernel(b);
    EXPECT_EQ(green_kernel_name(), b);
  }
  EXPECT_THROW(choose_green_kernel("sse9"), std::invalid_argument);
  EXPECT_EQ(green_kernel_name(), std::string("baseline"));  // a refused name changes nothing
  choose_green_kernel(builds.front());
}

using Scatter = void (*)(const GreenKernelData&, const int*, int, const double (*)[3],
                        const double (*)[3], const GreenScatterTarget&);

std::vector<std::pair<const char*, Scatter>> scatters() {
  std::vector<std::pair<const char*, Scatter>> k{{"dispatched", nullptr},
                                                 {"baseline", &green_scatter_forces_baseline}};
#if defined(__x86_64__)
  if (__builtin_cpu_supports("avx2")) k.emplace_back("avx2", &green_scatter_forces_avx2);
  if (has_avx512_kernel()) k.emplace_back("avx512", &green_scatter_forces_avx512);
#endif
  return k;
}

// The scattering pass adds each tet's forces to its vertices in list order; over an ascending
// list that is each point's incidence order, so it must give the gather's sums bit for bit:
// weighted (some weights zero) and masked, over lists that end in a full block of sixteen, a
// block of eight, a block of four and a single tet.
TEST(GreenScatterForces, BitIdenticalToTheGatherOfGreenPiola) {
  TetMesh mesh = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.06, 0.04), 7, 5, 4);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> jitter(-0.002, 0.002);
  for (Vec3& p : mesh.points) p += Vec3(jitter(rng), jitter(rng), jitter(rng));
  MaterialLaw law;
  law.strain = StrainMeasure::GreenLagrange;
  law.lambda = 5.0e5;
  law.mu = 3.0e4;
  for (const bool tensors : {false, true})
  for (const bool damped : {false, true}) {
    law.psi = damped ? 20 : 0;
    set_tet_tensors(law, tensors, static_cast<int>(mesh.tets.size()), rng);
    const LevelModel m = build_level_model(mesh, law);
    std::uniform_real_distribution<double> d(-3e-2, 3e-2);
    std::vector<Vec3> u(m.num_points()), v(m.num_points());
    for (int i = 0; i < m.num_points(); ++i) {
      u[i] = Vec3(d(rng), d(rng), d(rng));
      v[i] = 10 * Vec3(d(rng), d(rng), d(rng));
    }
    std::vector<int> list;
    for (int t = 0; t < m.num_tets(); ++t)
      if (t % 3 != 1) list.push_back(t);
    list.resize(16 * (list.size() / 16 - 1) + 8 + 5);
    std::vector<double> weight(m.num_tets(), 0.0);
    for (size_t k = 0; k < list.size(); ++k) weight[list[k]] = 0.25 * (k % 5 == 0 ? 0 : k % 4 + 1);
    std::vector<unsigned char> mask(m.num_points(), 0);
    for (int i = 0; i < m.num_points(); i += 2) mask[i] = 1;
    std::vector<TetGradients> per_tet(m.num_tets());
    for (int t : list) per_tet[t] = reference(m, t, u.data(), v.data());
    for (const bool weighted : {false, true}) {
      std::vector<Vec3> expected(m.num_points(), Vec3::Zero());
      for (int i = 0; i < m.num_points(); i += 2)
        for (int s = m.adj.inc_start[i]; s < m.adj.inc_start[i + 1]; ++s) {
          const int t = m.adj.inc_tet[s];
          if (!std::binary_search(list.begin(), list.end(), t)) continue;
          if (!weighted)
            expected[i] += per_tet[t][m.adj.inc_local[s]];
          else if (weight[t] != 0)
            expected[i] += weight[t] * per_tet[t][m.adj.inc_local[s]];
        }
      for (const auto& [name, scatter] : scatters()) {
        std::vector<Vec3> f(m.num_points(), Vec3::Zero());
        const double* w = weighted ? weight.data() : nullptr;
        const int n = static_cast<int>(list.size());
        if (scatter == nullptr)
          green_scatter_forces(m, list.data(), n, u.data(), v.data(), w, mask.data(), f.data());
        else
          scatter(green_kernel_data(m), list.data(), n,
                  reinterpret_cast<const double(*)[3]>(u.data()),
                  reinterpret_cast<const double(*)[3]>(v.data()),
                  GreenScatterTarget{w, mask.data(), reinterpret_cast<double(*)[3]>(f.data())});
        EXPECT_EQ(std::memcmp(expected.data(), f.data(), f.size() * sizeof(Vec3)), 0)
            << name << (weighted ? " weighted" : "") << (damped ? " damped" : "")
            << (tensors ? " per-tet tensors" : "");
      }
      // The same list from its contiguous copy (physics/packed_tets.hpp), the level's weights
      // gathered into it: the same bits.
      PackedTets packed;
      packed.pack(m.geo, list);
      std::vector<Vec3> f(m.num_points(), Vec3::Zero());
      green_scatter_packed(m, packed, u.data(), v.data(), weighted ? weight.data() : nullptr,
                           mask.data(), f.data());
      EXPECT_EQ(std::memcmp(expected.data(), f.data(), f.size() * sizeof(Vec3)), 0)
          << "packed" << (weighted ? " weighted" : "") << (damped ? " damped" : "")
          << (tensors ? " per-tet tensors" : "");
      // Every build over the packed copy, ∇N and the scales read from its blocks (whole rows
      // for the full blocks, the eight and the four after them; tet by tet for the padded
      // last one): the same bits.
      GreenKernelData d = green_kernel_data(m);
      d.grad = reinterpret_cast<const double(*)[4][3]>(packed.grad.data());
      d.tets = reinterpret_cast<const int(*)[4]>(packed.tets.data());
      d.volume = packed.volume.data();
      d.grad_blocks = packed.grad_blocks.data();
      if (tensors) {
        d.tet_scales = reinterpret_cast<const double(*)[10]>(packed.scales.data());
        d.scale_blocks = packed.scale_blocks.data();
      }
      ASSERT_EQ(packed.grad_blocks.size(), 12u * 16 * ((list.size() + 15) / 16));
      ASSERT_EQ(packed.scale_blocks.size(), tensors ? 10u * 16 * ((list.size() + 15) / 16) : 0u);
      std::vector<double> packed_weight(list.size());
      for (size_t k = 0; k < list.size(); ++k) packed_weight[k] = weight[list[k]];
      for (const auto& [name, scatter] : scatters()) {
        if (scatter == nullptr) continue;
        std::vector<Vec3> g(m.num_points(), Vec3::Zero());
        scatter(d, packed.order.data(), static_cast<int>(list.size()),
                reinterpret_cast<const double(*)[3]>(u.data()),
                reinterpret_cast<const double(*)[3]>(v.data()),
                GreenScatterTarget{weighted ? packed_weight.data() : nullptr, mask.data(),
                                   reinterpret_cast<double(*)[3]>(g.data())});
        EXPECT_EQ(std::memcmp(expected.data(), g.data(), g.size() * sizeof(Vec3)), 0)
            << name << " over blocks" << (weighted ? " weighted" : "")
            << (damped ? " damped" : "") << (tensors ? " per-tet tensors" : "");
      }
    }
  }
}

TEST(PackedTets, RecognisesOnlyTheListItPacked) {
  const LevelModel m = build_level_model(make_box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), 2, 2, 2),
                                         MaterialLaw{});
  const std::vector<int> list{1, 4, 5, 9, 30};
  PackedTets packed;
  EXPECT_FALSE(packed.packs(IndexSet::of(list)));
  packed.pack(m.geo, list);
  EXPECT_TRUE(packed.packs(IndexSet::of(list)));
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(packed.tets[k], m.geo.tets[list[k]]);
    EXPECT_EQ(packed.volume[k], m.geo.volume[list[k]]);
    EXPECT_EQ(packed.order[k], k);
  }
  const std::vector<int> same_ids = list;  // equal, but another list: not recognised
  EXPECT_FALSE(packed.packs(IndexSet::of(same_ids)));
  EXPECT_FALSE(packed.packs(IndexSet{list.data(), 4}));
  packed.clear();
  EXPECT_FALSE(packed.packs(IndexSet::of(list)));
}

// The packed pass gathers the level's weights once, not at every step: again only after pack()
// or once weight_source is reset (what LevelForceField::edit_tet_weights() does before the patch
// test adjusts them).
TEST(PackedTets, GathersTheWeightsAgainOnlyAfterAnEdit) {
  MaterialLaw law;
  law.strain = StrainMeasure::GreenLagrange;
  law.lambda = 5.0e5;
  law.mu = 3.0e4;
  const LevelModel m =
      build_level_model(make_box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), 3, 3, 3), law);
  std::vector<int> list;
  for (int t = 0; t < m.num_tets(); t += 2) list.push_back(t);
  std::vector<Vec3> u(m.num_points()), v(m.num_points(), Vec3::Zero());
  for (int i = 0; i < m.num_points(); ++i) u[i] = 1e-2 * Vec3(std::sin(i), std::cos(3 * i), 0.5);
  std::vector<double> weight(m.num_tets(), 0.5);
  PackedTets packed;
  packed.pack(m.geo, list);
  auto pass = [&] {
    std::vector<Vec3> f(m.num_points(), Vec3::Zero());
    green_scatter_packed(m, packed, u.data(), v.data(), weight.data(), nullptr, f.data());
    return f;
  };
  const std::vector<Vec3> first = pass();
  for (double& w : weight) w *= 2;  // edited without saying so: the gathered copy is used
  EXPECT_EQ(pass(), first);
  packed.weight_source = nullptr;   // said: gathered again
  const std::vector<Vec3> doubled = pass();
  double largest = 0;
  for (int i = 0; i < m.num_points(); ++i) {
    EXPECT_EQ(doubled[i], 2.0 * first[i]) << i;  // times two is exact
    largest = std::max(largest, first[i].norm());
  }
  EXPECT_GT(largest, 0.0);
}

}  // namespace
}  // namespace mrsim
