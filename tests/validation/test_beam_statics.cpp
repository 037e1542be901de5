// Clamped beam under gravity against validation.md §2.1–2.3 (structured Kuhn meshes, the same
// kind of mesh as the CalculiX C3D4 rows of the §2.3 table).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "simulation/beam_fixture.hpp"
#include "validation_record.hpp"

using namespace mrsim;
using namespace mrsim::testing;

namespace {
constexpr double kThreeD = 3.7618e-3;  // C3D10 h = 2.5 mm, gravity tip deflection (m)
}

TEST(BeamValidation, SuddenGravityOscillatesAboutTheStaticDeflectionAtF1) {
  // Undamped sudden load: the tip oscillates about its static deflection (validation §2.8);
  // the mean over whole periods is the static value, the period gives f1.
  const TetMesh mesh = beam_mesh(20);
  const double dt = 4e-5;  // half the exact Courant limit 8.489e-5 s of this mesh (§2.7)
  LevelSimulation sim(mesh, beam_setup(mesh, Integrator::ModifiedEuler, dt));
  std::vector<double> w;
  for (int k = 0; k < 30000; ++k) {
    sim.advance(1);
    w.push_back(-tip_deflection(sim, mesh));
  }
  const Oscillation o = measure_oscillation(w, dt);
  std::printf("20x4x4: static tip deflection %.5e m (%.3f of 3-D), f1 %.4f Hz over %d periods\n",
              o.mean, o.mean / kThreeD, o.frequency, o.periods);
  // §2.3 table, structured 20x4x4 (C3D4, same mesh kind): 2.9861e-3 m = 0.794 of 3-D, inside
  // the "-20 % at 4 across" band. The whole-period mean is good to ~0.5 % (higher modes).
  validation::Series series{
      "t (s)", "tip deflection -u_z (m)", {"t_s", "mrsim_m", "calculix_static_m"}, {}, "line"};
  for (size_t k = 0; k < w.size(); k += 100)
    series.rows.push_back({dt * static_cast<double>(k + 1), w[k], 2.9861e-3});
  validation::record({"beam_static_20x4x4", "Beam",
                      "Cantilever under sudden gravity, undamped: "
                      "mean tip deflection over whole periods (structured 20x4x4, 1920 tets)",
                      "tip deflection", "m", o.mean, 2.9861e-3,
                      "validation.md §2.3, CalculiX C3D4 on the same structured mesh "
                      "(0.794 of the 3-D value 3.7618e-3)",
                      0.99 * 2.9861e-3, 1.01 * 2.9861e-3, "±1 %",
                      "the whole-period mean is good to ~0.5 % (higher modes)"},
                     &series);
  validation::record({"beam_f1_20x4x4", "Beam",
                      "Cantilever under sudden gravity: period of the "
                      "tip oscillation (structured 20x4x4)",
                      "f1 (vertical bending)", "Hz", o.frequency, 11.624,
                      "validation.md §2.3, CalculiX C3D4 same mesh (the Kuhn split's vertical "
                      "mode; lumped mass lowers it ~0.2 %)",
                      0.985 * 11.624, 1.015 * 11.624, "±1.5 %", ""});
  EXPECT_NEAR(o.mean, 2.9861e-3, 0.01 * 2.9861e-3);
  EXPECT_GT(o.mean / kThreeD, 0.75);
  // The Kuhn split is anisotropic (§2.3): on this mesh CalculiX gives 10.872 Hz for one bending
  // direction and 11.624 Hz for the other, which is the vertical one excited by gravity here
  // (a lumped mass lowers it by ~0.2 %). Band: same-mesh value ±1.5 %, and within the
  // "+9 % at 4 across" band of the isotropic 3-D value 10.001 Hz widened by the 7 % anisotropy.
  EXPECT_NEAR(o.frequency, 11.624, 0.015 * 11.624);
  EXPECT_LT(o.frequency, 10.001 * 1.17);
  EXPECT_GE(o.periods, 10);
}

TEST(BeamValidation, DampedBeamRunToRestMatchesTheStaticBand) {
  // Stiffness-proportional damping D = βK (φ = βλ, ψ = βμ) with ζ1 ≈ 0.1 brings the coarse beam
  // to rest; explicit stability then needs dt ≈ dt_crit (√(1+ξ²) − ξ), ξ = β ω_max / 2 (§2.7).
  const TetMesh mesh = beam_mesh(10);
  const double dt = 5e-6;
  LevelSetup setup = beam_setup(mesh, Integrator::ModifiedEuler, dt);
  const double beta = 2.5e-3;  // s
  setup.law.phi = beta * setup.law.lambda;
  setup.law.psi = beta * setup.law.mu;
  LevelSimulation sim(mesh, setup);
  double previous = 0, w = 0;
  int steps = 0;
  validation::Series series{
      "t (s)", "tip deflection -u_z (m)", {"t_s", "mrsim_m", "calculix_static_m"}, {}, "line"};
  for (; steps < 400000; steps += 2000) {
    sim.advance(2000);
    w = -tip_deflection(sim, mesh);
    series.rows.push_back({(steps + 2000) * dt, w, 1.95e-3});
    if (steps > 20000 && std::abs(w - previous) < 1e-7 * w) break;
    previous = w;
  }
  std::printf("10x2x2 at rest after %.3f s: tip deflection %.5e m (%.3f of 3-D)\n", steps * dt, w,
              w / kThreeD);
  EXPECT_LT(steps, 400000);  // it did come to rest
  // §2.3: structured 10x2x2 (2 across) gives 1.9500e-3 m = 0.518 of 3-D ("order of magnitude,
  // -50 %" at 2 across). CalculiX C3D4 on this same structured split: 1.9500e-3 m; a damped
  // explicit run driven to rest should reproduce a linear static solve (§2.3): within 0.5 %.
  validation::record({"beam_static_10x2x2", "Beam",
                      "Cantilever under gravity, damped to rest "
                      "(β = 2.5 ms stiffness damping; structured 10x2x2, 240 tets)",
                      "tip deflection", "m", w, 1.95e-3,
                      "validation.md §2.3, CalculiX C3D4 linear static on the same mesh "
                      "(0.518 of the 3-D value: 2 elements across)",
                      0.995 * 1.95e-3, 1.005 * 1.95e-3, "±0.5 %",
                      "a damped explicit run at rest is the linear static solve"},
                     &series);
  EXPECT_NEAR(w, 1.95e-3, 0.005 * 1.95e-3);
}
