// Damping ratio of the first bending mode from the logarithmic decrement, against the
// prediction of the strain-rate damping (validation.md §2.8). The damping stress is
// φ tr(ε̇) I + 2ψ ε̇ (physics/stress.hpp, cauchy_stress); with φ = βλ and ψ = βμ it is β times
// the elastic stress of ε̇, so the damping matrix is D = βK exactly (the Cauchy edge matrices
// are D = φA + ψB, K = λA + μB): stiffness-proportional Rayleigh damping, ζ1 = β ω1 / 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "mesh/mesh_reader.hpp"
#include "physics/internal_force.hpp"
#include "simulation/beam_fixture.hpp"
#include "simulation/stable_step.hpp"
#include "validation/modal_measure.hpp"
#include "validation/validation_record.hpp"

using namespace mrsim;
using namespace mrsim::testing;

namespace {

constexpr double kZeta = 0.03;  // target ζ1 (0.03-0.05 asked; the low end allows the largest
                                // step: dt ≈ 2/(β ω_max²) once ξ >> 1)
constexpr double kBand = 0.07;  // §2.8: CalculiX measured ζ 7 % high (higher modes, 3 cycles)
constexpr int kFirstLobe = 1;   // skip the first cycle: the higher modes (ζ2 ≈ 5 ζ1) die in it
constexpr int kLobes = 4;       // then 3 decrements (cycles 2 to 5), as CalculiX's 3 cycles
constexpr int kSample = 1000;   // damped steps per series sample (~2 ms)

// ω_max² = largest eigenvalue of M⁻¹K over the free points (validation.md §2.7), by power
// iteration on the undamped internal force; the Rayleigh quotient converges from below (on
// beam L2 to 8 digits within 100 iterations: the top mode is well separated).
double omega_max(const TetMesh& mesh, const LevelSetup& setup) {
  const LevelModel model = build_level_model(mesh, setup.law);
  const size_t n = mesh.points.size();
  std::vector<Vec3> x(n), v(n, Vec3::Zero()), f(n);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-1, 1);
  for (size_t i = 0; i < n; ++i)
    x[i] = setup.fixed[i] ? Vec3::Zero() : Vec3(d(rng), d(rng), d(rng));
  ForceWorkspace ws;
  double lambda = 0;
  for (int it = 0; it < 200; ++it) {
    internal_forces(model, x.data(), v.data(), f.data(), ws);
    double dot = 0, norm = 0;
    for (size_t i = 0; i < n; ++i) {
      const Vec3 y = setup.fixed[i] ? Vec3::Zero() : Vec3(-f[i] / model.mass[i]);
      dot += model.mass[i] * x[i].dot(y);  // M-inner product: M⁻¹K is M-symmetric
      norm += model.mass[i] * x[i].squaredNorm();
      x[i] = y;
    }
    lambda = dot / norm;
    double scale = 0;
    for (const Vec3& y : x) scale = std::max(scale, y.norm());
    for (Vec3& y : x) y /= scale;
  }
  return std::sqrt(lambda);
}

struct TipRecord {
  std::vector<double> w;  // tip deflection (m, down) after every step
  double dt = 0;
};

TipRecord run(const TetMesh& mesh, LevelSetup setup, double duration) {
  LevelSimulation sim(mesh, setup);
  TipRecord r;
  r.dt = setup.dt;
  const long steps = std::lround(duration / setup.dt);
  r.w.reserve(steps);
  for (long k = 0; k < steps; ++k) {
    sim.advance(1);
    r.w.push_back(-tip_deflection(sim, mesh));
  }
  return r;
}

// ζ from the decay of the peak-to-peak swing of successive cycles: independent of the static
// value (a cross-check of the decrement about the static deflection).
double peak_to_peak_zeta(const TipRecord& r, double level) {
  std::vector<double> neg(r.w.size());
  for (size_t k = 0; k < r.w.size(); ++k) neg[k] = -r.w[k];
  const auto up = lobe_maxima(r.w, r.dt, level), down = lobe_maxima(neg, r.dt, -level);
  std::vector<Extremum> swing;
  for (size_t k = 0; k < up.size() && k < down.size(); ++k)
    swing.push_back({up[k].t, up[k].value + down[k].value});
  if (swing.size() <= static_cast<size_t>(kLobes)) return std::nan("");
  return damping_ratio(log_decrement(swing, kFirstLobe, kLobes));
}

}  // namespace

// Breaking it: damping that is not proportional to K (φ, ψ swapped, or the damping stress
// taken from ε instead of ε̇) or an integrator that adds or removes energy of order 7 % per
// decade of cycles moves ζ out of the band; with D = 0 the decrement is ~0.
TEST(DampingRatio, LogDecrementMatchesStiffnessProportionalPrediction) {
  // The gmsh 1641-tet level of the bundled beam: isotropic, so the vertical bending mode is
  // clean (§2.8: the structured Kuhn meshes beat between two frequencies).
  const TetMesh mesh = bundled_beam_level(2);
  const double h = shortest_edge(mesh);
  // Undamped run on the same mesh: ω1 and the static deflection the decay is measured about.
  LevelSetup setup = beam_setup(mesh, Integrator::ModifiedEuler, 0);
  setup.dt = 0.5 * h / setup.law.p_wave_speed();
  const TipRecord undamped = run(mesh, setup, 1.0);
  const Oscillation o = measure_oscillation(undamped.w, undamped.dt);
  const double w1 = 2 * std::numbers::pi * o.frequency;
  // β for ζ1 = 0.03, and the step explicit stability then needs (§2.7): the exact limit
  // 2/ω_max shrinks by √(1+ξ²) - ξ, ξ = β ω_max / 2 (modified Euler sees the damping force of
  // the previous velocity, the lagged central difference the formula is for). 0.9 of it.
  const double beta = 2 * kZeta / w1;
  const double wmax = omega_max(mesh, setup);
  const double xi = beta * wmax / 2;
  LevelSetup damped_setup = setup;
  damped_setup.law.phi = beta * setup.law.lambda;
  damped_setup.law.psi = beta * setup.law.mu;
  damped_setup.dt = 0.9 * (2 / wmax) * (std::sqrt(1 + xi * xi) - xi);
  const TipRecord damped = run(mesh, damped_setup, (kLobes + 2) / o.frequency);

  const auto peaks = lobe_maxima(damped.w, damped.dt, o.mean);
  ASSERT_GT(peaks.size(), static_cast<size_t>(kLobes));
  const double delta = log_decrement(peaks, kFirstLobe, kLobes);
  const double zeta = damping_ratio(delta), predicted = beta * w1 / 2;
  const double fd = (kLobes - kFirstLobe) / (peaks[kLobes].t - peaks[kFirstLobe].t);
  const double p2p = peak_to_peak_zeta(damped, o.mean);
  std::printf(
      "damping L2: f1 %.4f Hz, static %.4e m; beta %.3e s, omega_max %.0f rad/s, xi "
      "%.2f, dt %.2e s; zeta %.4f (peak-to-peak %.4f) vs beta omega1/2 = %.4f (%+.2f %%); "
      "f_d %.4f Hz (predicted %.4f)\n",
      o.frequency, o.mean, beta, wmax, xi, damped_setup.dt, zeta, p2p, predicted,
      100 * (zeta / predicted - 1), fd, o.frequency * std::sqrt(1 - predicted * predicted));
  EXPECT_NEAR(zeta, predicted, kBand * predicted);
  EXPECT_NEAR(p2p, predicted, kBand * predicted);

  validation::Check c;
  c.id = "damping_ratio_beam_L2";
  c.group = "Damping";
  c.title = "First-mode damping ratio from the log decrement, beam L2 (1641 tets), D = beta K";
  c.quantity = "zeta1";
  c.measured = zeta;
  c.reference = predicted;
  c.reference_source =
      "validation.md §2.8: Rayleigh damping beta K gives zeta1 = beta omega1/2 "
      "(omega1 measured undamped on the same mesh); zeta = delta / "
      "sqrt(4 pi^2 + delta^2)";
  c.lower = (1 - kBand) * predicted;
  c.upper = (1 + kBand) * predicted;
  c.tolerance = "±7 % (§2.8: CalculiX measured zeta 7 % high from higher modes over 3 cycles)";
  char note[300];
  std::snprintf(note, sizeof note,
                "phi = beta lambda, psi = beta mu, beta = %.3e s; decrement over cycles %d-%d "
                "about the undamped static deflection %.4e m; peak-to-peak estimate %.4f; dt "
                "%.2e s = 0.9 x exact limit (xi = %.1f)",
                beta, kFirstLobe + 1, kLobes + 1, o.mean, p2p, damped_setup.dt, xi);
  c.note = note;
  validation::Series s;
  s.x_label = "t (s)";
  s.y_label = "tip deflection (m, down)";
  s.columns = {"t", "damped", "static"};
  for (size_t k = kSample - 1; k < damped.w.size(); k += kSample)
    s.rows.push_back({damped.dt * static_cast<double>(k + 1), damped.w[k], o.mean});
  validation::record(c, &s);
}
