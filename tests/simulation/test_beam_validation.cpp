// Clamped beam under gravity against validation.md §2.1–2.3 (structured Kuhn meshes, the same
// kind of mesh as the CalculiX C3D4 rows of the §2.3 table).
#include <gtest/gtest.h>

#include <cstdio>

#include "beam_fixture.hpp"

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
  // §2.3 table, structured 20x4x4 (C3D4, same mesh kind): 2.9861e-3 m = 0.794 of 3-D.
  EXPECT_NEAR(o.mean / kThreeD, 0.794, 0.02);
  // The Kuhn split is anisotropic (§2.3): on this mesh CalculiX gives 10.872 Hz for one bending
  // direction and 11.624 Hz for the other, which is the vertical one excited by gravity here
  // (a lumped mass lowers it by ~0.2 %). Band: same-mesh value ±1.5 %, and within the
  // "+9 % at 4 across" band of the isotropic 3-D value 10.001 Hz widened by the 7 % anisotropy.
  EXPECT_NEAR(o.frequency, 11.624, 0.015 * 11.624);
  EXPECT_LT(o.frequency, 10.001 * 1.17);
  EXPECT_GE(o.periods, 10);
}
