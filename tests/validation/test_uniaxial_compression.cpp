// Uniaxial compression of a block with free lateral faces (validation.md §2.5): the exact
// solution is affine, so linear tets must reproduce it exactly (the patch test). The exact
// displacement is imposed on every point and the internal forces are evaluated: the top face
// carries the analytic end force, every interior and lateral-face point carries nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "mesh/box_mesh.hpp"
#include "physics/internal_force.hpp"
#include "validation/validation_record.hpp"

using namespace mrsim;

namespace {

// §2.5: the 20 x 20 x 40 mm block CalculiX squeezed by 10 % (F = -40.000 N), E = 1e6, ν = 0.3.
constexpr double kB = 0.02, kH0 = 0.04, kArea = kB * kB;
constexpr double kE = 1.0e6, kNu = 0.3;
constexpr double kTol = 1e-9;  // a patch test: exact up to round-off

MaterialLaw law(StrainMeasure strain) {
  MaterialLaw l;
  l.strain = strain;
  l.lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));
  l.mu = kE / (2 * (1 + kNu));
  l.density = 1000;
  return l;
}

bool on_top(const Vec3& p) { return p.z() > kH0 - 1e-9; }
bool on_bottom(const Vec3& p) { return p.z() < 1e-9; }

// 4 x 4 x 8 cells with every interior point moved by up to ±20 % of a cell, so no force
// cancels by the symmetry of the Kuhn split.
TetMesh jittered_block() {
  TetMesh m = make_box_mesh(Vec3(0, 0, 0), Vec3(kB, kB, kH0), 4, 4, 8);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> d(-0.2, 0.2);
  const double h = kB / 4;
  for (Vec3& p : m.points) {
    const bool interior = p.x() > 1e-9 && p.x() < kB - 1e-9 && p.y() > 1e-9 && p.y() < kB - 1e-9 &&
                          !on_top(p) && !on_bottom(p);
    if (interior) p += h * Vec3(d(rng), d(rng), d(rng));
  }
  return m;
}

struct FaceForces {
  double top = 0;         // N, external force the top face needs: -Σ internal f_z
  double typical = 0;     // N, |top| / number of top points: a typical nodal force
  double free_worst = 0;  // N, largest |f| on an interior or lateral-face point
  int free_points = 0;
};

/// Internal forces of the affine field u = diag(sx, sx, sz) X - X (stretches sx, sz).
FaceForces affine_forces(const TetMesh& mesh, StrainMeasure strain, double sx, double sz) {
  const LevelModel model = build_level_model(mesh, law(strain));
  std::vector<Vec3> u(mesh.points.size()), v(mesh.points.size(), Vec3::Zero()), f(u.size());
  for (size_t i = 0; i < u.size(); ++i) {
    const Vec3& X = mesh.points[i];
    u[i] = Vec3((sx - 1) * X.x(), (sx - 1) * X.y(), (sz - 1) * X.z());
  }
  ForceWorkspace ws;
  internal_forces(model, u.data(), v.data(), f.data(), ws);
  FaceForces r;
  int top = 0;
  for (size_t i = 0; i < u.size(); ++i) {
    if (on_top(mesh.points[i])) {
      r.top -= f[i].z();
      ++top;
    } else if (!on_bottom(mesh.points[i])) {
      r.free_worst = std::max(r.free_worst, f[i].norm());
      ++r.free_points;
    }
  }
  r.typical = std::abs(r.top) / top;
  return r;
}

/// St Venant–Kirchhoff with E_xx = -ν E_zz exactly (§2.5): lateral stretch for λ_z.
double svk_lateral(double lz) { return std::sqrt(1 - kNu * (lz * lz - 1)); }
/// Nominal stress P_zz = E λ_z (λ_z² - 1) / 2 (§2.5).
double svk_nominal(double lz) { return kE * lz * (lz * lz - 1) / 2; }

validation::Check base(const std::string& id, const std::string& title) {
  validation::Check c;
  c.id = id;
  c.group = "Uniaxial compression (patch test)";
  c.title = title;
  return c;
}

// Top-face force against the analytic E A ε or P_zz A0, relative 1e-9.
void record_force(validation::Check c, const FaceForces& r, double reference,
                  const std::string& source) {
  c.quantity = "top-face force";
  c.unit = "N";
  c.measured = r.top;
  c.reference = reference;
  c.reference_source = source;
  c.lower = reference - kTol * std::abs(reference);
  c.upper = reference + kTol * std::abs(reference);
  c.tolerance = "relative 1e-9 (affine field: exact up to round-off)";
  c.note =
      "structured 4x4x8-cell block (20x20x40 mm), interior points jittered by up to 20 % "
      "of a cell; the exact affine displacement is imposed on every point";
  validation::record(c);
}

// Largest force on an interior or lateral-face point (traction-free), relative to a typical
// nodal force of the top face: zero up to round-off.
void record_free(validation::Check c, const FaceForces& r) {
  c.quantity = "largest free-point force / typical top nodal force";
  c.unit = "";
  c.measured = r.free_worst / r.typical;
  c.reference = 0;
  c.reference_source =
      "validation.md §2.5: the solution is affine, linear tets reproduce it "
      "exactly (patch test); lateral faces and interior are traction-free";
  c.lower = 0;
  c.upper = kTol;
  c.tolerance = "below 1e-9 of a typical nodal force";
  c.note = std::to_string(r.free_points) + " interior and lateral-face points";
  validation::record(c);
}

}  // namespace

// Cauchy: ε = -δ/H0 = -10 %, lateral strain -ν ε, F = E A ε = -40 N (CalculiX: -40.000 N).
// Breaking it: any error in the stiffness (λ/μ swapped, a wrong volume or gradient) changes F
// at the percent level, far beyond 1e-9; a wrong lateral strain loads the lateral faces.
TEST(UniaxialCompression, CauchyAffineFieldGivesEAEpsAndTractionFreeSides) {
  const TetMesh mesh = jittered_block();
  const double eps = -0.1;
  const FaceForces r = affine_forces(mesh, StrainMeasure::Cauchy, 1 - kNu * eps, 1 + eps);
  const double reference = kE * kArea * eps;
  std::printf(
      "uniaxial Cauchy eps = %.2f: top force %.12f N (E A eps = %.12f N), free points "
      "%.2e of a typical nodal force %.4f N\n",
      eps, r.top, reference, r.free_worst / r.typical, r.typical);
  EXPECT_NEAR(r.top, reference, kTol * std::abs(reference));
  EXPECT_LT(r.free_worst, kTol * r.typical);
  EXPECT_GT(r.free_points, 50);
  record_force(
      base("uniaxial_cauchy_force", "Cauchy, 10 % squeeze of a 20x20x40 mm block: end force"), r,
      reference, "validation.md §2.5 (linear theory F = E A eps; CalculiX -40.000 N)");
  record_free(base("uniaxial_cauchy_free_points",
                   "Cauchy, 10 % squeeze: force on interior and lateral-face points"),
              r);
}

// SVK (green_lagrange): λ_z = 0.9, λ_x = √(1 - ν(λ_z² - 1)), P_zz A0 = E λ_z (λ_z² - 1)/2 A0.
// Breaking it: a Green force that drops GᵀG, or returns S instead of P = F S, misses P_zz by
// 10 % (λ_z) and puts forces on the sides.
TEST(UniaxialCompression, SvkAffineFieldGivesTheNominalStressAndTractionFreeSides) {
  const TetMesh mesh = jittered_block();
  const double lz = 0.9;
  const FaceForces r = affine_forces(mesh, StrainMeasure::GreenLagrange, svk_lateral(lz), lz);
  const double reference = svk_nominal(lz) * kArea;
  std::printf(
      "uniaxial SVK lambda_z = %.2f (lambda_x = %.6f): top force %.12f N (P_zz A0 = "
      "%.12f N), free points %.2e of a typical nodal force\n",
      lz, svk_lateral(lz), r.top, reference, r.free_worst / r.typical);
  EXPECT_NEAR(r.top, reference, kTol * std::abs(reference));
  EXPECT_LT(r.free_worst, kTol * r.typical);
  record_force(base("uniaxial_svk_force", "SVK, stretch 0.9 of a 20x20x40 mm block: end force"), r,
               reference, "validation.md §2.5 (SVK: P_zz = E lz (lz^2-1)/2, lx exact)");
  record_free(base("uniaxial_svk_free_points",
                   "SVK, stretch 0.9: force on interior and lateral-face points"),
              r);
}

// §2.5: SVK softens in compression and has a limit point at λ_z = 1/√3 where dP/dλ = 0. The
// end force is the cubic P(λ_z) A0 exactly, so its central difference over ±h at 1/√3 is
// E h²/2 (not 0: the cubic's third-order term), against E at λ_z = 1. Breaking it: a force off
// by any λ-dependent factor moves the extremum and gives a slope of order E (λ - 1/√3).
TEST(UniaxialCompression, SvkEndForceHasItsLimitPointAtOneOverRootThree) {
  const TetMesh mesh = jittered_block();
  const double lc = 1 / std::sqrt(3.0), h = 0.01;
  auto force = [&](double lz) {
    return affine_forces(mesh, StrainMeasure::GreenLagrange, svk_lateral(lz), lz).top;
  };
  const double below = force(lc - h), at = force(lc), above = force(lc + h);
  const double slope = (above - below) / (2 * h * kArea) / kE;  // dP/dλ in units of E
  const double reference = h * h / 2;
  std::printf(
      "SVK limit point: end force %.9f / %.9f / %.9f N at lambda_z = %.3f / %.4f / "
      "%.3f; secant dP/dlambda = %.3e E (cubic: %.3e E)\n",
      below, at, above, lc - h, lc, lc + h, slope, reference);
  EXPECT_LT(at, below);  // the most compressive end force of the three
  EXPECT_LT(at, above);
  EXPECT_NEAR(slope, reference, kTol);
  validation::Check c = base("uniaxial_svk_limit_point",
                             "SVK limit point: slope of the end force at lambda_z = 1/sqrt(3)");
  c.quantity = "dP/dlambda (central difference over +-0.01) / E";
  c.measured = slope;
  c.reference = reference;
  c.reference_source =
      "validation.md §2.5: SVK limit point at lambda_z = 1/sqrt(3), dP/dlambda "
      "= 0; the central difference of the cubic P is E h^2/2";
  c.lower = reference - kTol;
  c.upper = reference + kTol;
  c.tolerance = "±1e-9 E (slope at lambda_z = 1 is 1 E)";
  c.note = "end forces " + std::to_string(below) + " / " + std::to_string(at) + " / " +
           std::to_string(above) + " N at lambda_z = 0.567 / 0.577 / 0.587";
  validation::record(c);
}
