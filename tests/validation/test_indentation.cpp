// A rigid tool pushing an elastic block (validation.md §2.9): Hertz's sphere and Boussinesq's
// flat punch on a block graded under the tool (tests/simulation/contact_fixture.hpp), with the
// penalty contact of docs/contact.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "simulation/contact_fixture.hpp"
#include "validation_record.hpp"

namespace mrsim {
namespace {

using testing::courant_dt;
using testing::IndentedBlock;
using testing::vertical_tool;

struct Sample {
  double time;         // s
  double depth;        // m, the tool's depth below the undeformed surface
  double penetration;  // m, deepest skin vertex inside the tool
  double force;        // N, upward force on the tool
};

// Runs to t_end, sampling every `every` steps while the tool is below the surface (its working
// end `tip` m below the tool frame's origin).
std::vector<Sample> indent(HierarchicalSimulation& sim, double dt, double t_end, int every,
                           double tip) {
  std::vector<Sample> out;
  const int steps = static_cast<int>(std::lround(t_end / dt));
  for (int s = 0; s < steps; s += every) {
    sim.advance(every);
    const SkinContact& c = *sim.contact();
    const double depth = -(c.tool(0).trajectory.pose(sim.time()).position.z() - tip);
    if (depth > 0) out.push_back({sim.time(), depth, c.max_depth(0), c.tool_force(0).z()});
  }
  return out;
}

// Least-squares slope of log F against log d over the samples with d in [lo, hi].
double log_slope(const std::vector<Sample>& samples, double lo, double hi) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const Sample& s : samples)
    if (s.depth >= lo && s.depth <= hi && s.force > 0) {
      const double x = std::log(s.depth), y = std::log(s.force);
      n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

double hertz_force(const IndentedBlock& block, double R, double d) {
  return 4.0 / 3.0 * block.e_star() * std::sqrt(R) * std::pow(d, 1.5);
}

// Sphere R = 5 mm into a 40 x 40 x 20 mm block (E = 10 kPa, nu = 0.3) to 0.5 mm over 0.5 s,
// cells of 0.4 mm under the tool (contact radius 1.0-1.6 mm: 2.5-4 cells), automatic penalty.
// A wrong contact normal, depth or force scatter would bend the slope or shift the force.
TEST(Indentation, HertzSphereForceGrowsAsDepthToTheThreeHalves) {
  const IndentedBlock block;
  const TetMesh mesh = block.mesh();
  const double R = 5e-3, d_max = 5e-4, t_load = 0.5;
  HierarchySetup s =
      block.setup(mesh, vertical_tool({ToolShapeKind::Sphere, R, 0}, R + 2e-5, R - d_max, t_load));
  s.dt = courant_dt(mesh, s.law);
  HierarchicalSimulation sim({&mesh}, s);
  const std::vector<Sample> samples = indent(sim, s.dt, t_load, 50, R);
  ASSERT_GT(samples.size(), 50u);
  const double slope = log_slope(samples, 2e-4, 5e-4);
  double worst = 0, worst_signed = 0, deepest = 0;
  validation::Series series{
      "depth d (m)", "force on the tool (N)", {"depth_m", "mrsim_N", "hertz_N"}, {}, "loglog"};
  for (const Sample& x : samples) {
    deepest = std::max(deepest, x.penetration);
    series.rows.push_back({x.depth, x.force, hertz_force(block, R, x.depth)});
    if (x.depth < 2.5e-4) continue;
    const double ratio = x.force / hertz_force(block, R, x.depth) - 1;
    if (std::abs(ratio) > worst) worst = std::abs(ratio), worst_signed = ratio;
  }
  const Sample& last = samples.back();
  const double dent = last.depth - last.penetration;
  std::printf(
      "Hertz: slope %.3f on d in [0.2, 0.5] mm; F/F_hertz(d) worst %.3f for d >= 0.25 mm; "
      "at d = %.3f mm: F = %.4e N; against the dent made (d - penetration = %.3f mm): "
      "%.3f; deepest penetration %.4f mm = %.2f h0\n",
      slope, 1 + worst_signed, last.depth * 1e3, last.force, dent * 1e3,
      last.force / hertz_force(block, R, dent), deepest * 1e3, deepest / block.h0);
  const std::string mesh_text = "graded block 40x40x20 mm, 0.4 mm cells under the tool, " +
                                std::to_string(mesh.tets.size()) + " tets";
  validation::record(
      {"indentation_hertz_slope", "Indentation",
       "Sphere R = 5 mm to 0.5 mm: log-log slope of F(d) on [0.2, 0.5] mm (" + mesh_text + ")",
       "slope", "", slope, 1.5, "validation.md §2.9 (Hertz: F ∝ d^3/2)", 1.35, 1.65, "±0.15",
       "contact radius 2.5-4 cells"},
      &series);
  validation::record({"indentation_hertz_force", "Indentation",
                      "Sphere R = 5 mm: worst F / F_Hertz(d) for d in [0.25, 0.5] mm", "ratio", "",
                      1 + worst_signed, 1.0, "validation.md §2.9 (Hertz, ±15 % sanity bound)", 0.85,
                      1.15, "±15 %", ""});
  validation::record({"indentation_sphere_penetration", "Indentation",
                      "Sphere: deepest penalty penetration, in cells of the finest mesh", "h0", "",
                      deepest / block.h0, 0.0, "docs/contact.md (penalty 'auto')", 0, 0.25,
                      "< 0.25 cell", ""});
  EXPECT_NEAR(slope, 1.5, 0.15);
  EXPECT_LT(worst, 0.15);
  EXPECT_LT(deepest, 0.25 * block.h0);  // the penalty's penetration: a fraction of a cell
}

// Flat punch a = 2 mm to d = 0.1 mm over 0.3 s, held 0.1 s: F = 2 a E* d within 15 %.
TEST(Indentation, FlatPunchForceIsWithinFifteenPercentOfBoussinesq) {
  const IndentedBlock block;
  const TetMesh mesh = block.mesh();
  const double a = 2e-3, d = 1e-4, t_load = 0.3, t_end = 0.4;
  HierarchySetup s =
      block.setup(mesh, vertical_tool({ToolShapeKind::FlatCylinder, a, 5e-3}, 2e-5, -d, t_load));
  s.dt = courant_dt(mesh, s.law);
  HierarchicalSimulation sim({&mesh}, s);
  const std::vector<Sample> samples = indent(sim, s.dt, t_end, 50, 0.0);
  const Sample& last = samples.back();
  const double boussinesq = 2 * a * block.e_star() * d;
  std::printf(
      "Boussinesq: F = %.4e N, 2 a E* d = %.4e N, ratio %.3f; penetration %.4f mm; "
      "against the dent made: %.3f\n",
      last.force, boussinesq, last.force / boussinesq, last.penetration * 1e3,
      last.force / (2 * a * block.e_star() * (d - last.penetration)));
  validation::Series series{
      "t (s)", "force on the punch (N)", {"t_s", "mrsim_N", "boussinesq_N"}, {}, "line"};
  for (const Sample& x : samples)
    series.rows.push_back({x.time, x.force, 2 * a * block.e_star() * x.depth});
  validation::record({"indentation_punch", "Indentation",
                      "Flat punch a = 2 mm pressed 0.1 mm, held: F / (2 a E* d)", "ratio", "",
                      last.force / boussinesq, 1.0,
                      "validation.md §2.9 (Boussinesq half-space, ±15 % sanity bound)", 0.85, 1.15,
                      "±15 %", "finite block on a fixed base: stiffer than a half-space"},
                     &series);
  EXPECT_NEAR(last.force / boussinesq, 1.0, 0.15);
  EXPECT_LT(last.penetration, 0.25 * block.h0);
}

}  // namespace
}  // namespace mrsim
