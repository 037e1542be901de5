// First bending frequency of each bundled beam level alone (scenarios/meshes/beam_L0..L2.vtu,
// the validation cantilever of validation.md §2), against the §2.3 locking table, and the
// spread of f1 across the levels: [DDCB01]'s claim that the damped vibration modes are nearly
// unchanged across refinement levels, measured on this model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "mesh/mesh_reader.hpp"
#include "simulation/beam_fixture.hpp"
#include "simulation/stable_step.hpp"
#include "validation/modal_measure.hpp"
#include "validation/validation_record.hpp"

using namespace mrsim;
using namespace mrsim::testing;

namespace {

constexpr double kThreeD = 10.001;  // Hz, f1 of C3D10 h = 2.5 mm (validation.md §2.2, §2.3)
constexpr double kThreeDDeflection = 3.7618e-3;  // m, gravity, same C3D10 run (§2.3)
constexpr double kDuration = 1.2;                // s: 12 or more periods of f1
constexpr int kSample = 25;                      // steps per sample of the series

struct BeamLevel {
  int level = 0;
  TetMesh mesh;
  double shortest = 0, mean_edge = 0;  // m
  double across = 0;  // elements across the thickness, by tet count against the gmsh rows
};

double mean_edge(const TetMesh& mesh) {
  std::set<std::pair<int, int>> edges;
  for (const Tet& t : mesh.tets)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) edges.insert(std::minmax(t[a], t[b]));
  double sum = 0;
  for (auto [i, j] : edges) sum += (mesh.points[i] - mesh.points[j]).norm();
  return sum / static_cast<double>(edges.size());
}

// Elements across the 20 mm thickness. The gmsh rows of §2.3 fill the same box: h = 5 mm
// (4 across) with 1787 tets, so a mesh of n tets has the equivalent size 5 mm (1787/n)^(1/3).
// (The mean edge, printed too, runs ~20 % above h: it counts face and body diagonals.)
BeamLevel load_level(int level) {
  BeamLevel b;
  b.level = level;
  b.mesh = bundled_beam_level(level);
  b.shortest = shortest_edge(b.mesh);
  b.mean_edge = mean_edge(b.mesh);
  b.across = kBeamH / (5e-3 * std::cbrt(1787.0 / static_cast<double>(b.mesh.tets.size())));
  return b;
}

// The band §2.3 allows for f1 at `across` elements across the thickness (ν = 0.3). Linear tets
// are too stiff, so f1 lies above the 3-D value; the lumped mass lowers it by 0.2 % and the
// period measurement is good to a few 0.1 %: lower bound 1 % under 10.001 Hz. Upper bound from
// the suggested tolerances: "at 4 across f1 +9 %"; "at about 2 across only order of magnitude
// (-50 %)" on the deflection, i.e. a stiffness up to 2x and f1 up to √2 x (f1 goes as the square
// root of the stiffness, §2.3). For a mesh coarser than the row the error is scaled by
// (row / across)², the asymptotic O(h²) rate (the measured rate between 2 and 4 across is 3.2
// per halving, slower, so this overestimates: safe). Where no bound is left (coarser than any
// row) §2.3 allows an order of magnitude only.
struct Band {
  double lower = 0, upper = 0, reference = 0;
  std::string source, tolerance;
};

Band f1_band(double across) {
  Band b;
  b.lower = 0.99 * kThreeD;
  auto scale = [&](double row) { return std::max(1.0, (row / across) * (row / across)); };
  if (across >= 3) {
    b.upper = kThreeD * (1 + 0.09 * scale(4));
    b.reference = 10.855;
    b.source =
        "validation.md §2.3 row 'gmsh h = 5 mm' (1787 tets; lumped f1 10.855 Hz, §2.2) "
        "and suggested tolerance 'at 4 across f1 +9 %'";
    b.tolerance = "-1 % / +9 % x (4/across)^2 of the 3-D 10.001 Hz";
  } else if (across >= 1.5 && 0.5 * scale(2) < 0.9) {
    b.upper = kThreeD / std::sqrt(1 - 0.5 * scale(2));
    b.reference = 12.711;
    b.source =
        "validation.md §2.3 row 'gmsh h = 10 mm' (254 tets, 12.711 Hz) and suggested "
        "tolerance 'at about 2 across only order of magnitude (-50 %)'";
    b.tolerance =
        "-1 % / deflection -50 % x (2/across)^2 -> f1 x 1/sqrt(1 - that) of the 3-D "
        "10.001 Hz";
  } else {
    b.upper = 10 * kThreeD;
    b.reference = kThreeD;
    b.source =
        "validation.md §2.3: coarser than every row (2 across: 'only order of "
        "magnitude'); 3-D value C3D10 h = 2.5 mm";
    b.tolerance = "one-sided: above -1 % of the 3-D value, below 10x (order of magnitude)";
  }
  return b;
}

struct LevelRun {
  std::vector<double> w;  // tip deflection (m, positive down) after every step
  Oscillation o;
  double dt = 0;
};

// Sudden gravity, face x = 0 clamped, Cauchy strain, modified Euler; strain-rate damping ψ
// (φ = 0) as in scenarios/beam_adaptive.yaml when psi > 0.
LevelRun run(const TetMesh& mesh, double dt, double psi) {
  LevelSetup setup = beam_setup(mesh, Integrator::ModifiedEuler, dt);
  setup.law.psi = psi;
  LevelSimulation sim(mesh, setup);
  LevelRun r;
  r.dt = dt;
  const int steps = static_cast<int>(std::lround(kDuration / dt));
  r.w.reserve(steps);
  for (int k = 0; k < steps; ++k) {
    sim.advance(1);
    r.w.push_back(-tip_deflection(sim, mesh));
  }
  r.o = measure_oscillation(r.w, dt);
  return r;
}

validation::Series tip_series(const std::vector<const LevelRun*>& runs,
                              const std::vector<std::string>& names) {
  validation::Series s;
  s.x_label = "t (s)";
  s.y_label = "tip deflection (m, down)";
  s.columns = {"t"};
  s.columns.insert(s.columns.end(), names.begin(), names.end());
  for (size_t k = kSample - 1; k < runs.front()->w.size(); k += kSample) {
    std::vector<double> row = {runs.front()->dt * static_cast<double>(k + 1)};
    for (const LevelRun* r : runs) row.push_back(r->w[k]);
    s.rows.push_back(row);
  }
  return s;
}

// One step for every level: half the Courant estimate (shortest edge / c_p) of the finest
// level (validation.md §2.7: dt <= 0.5 h_min / c_p is safe, the exact limit being 0.62-0.76
// h_min / c_p on gmsh meshes; ψ = 2 Pa.s lowers it by ~8 % only, ξ ≈ (ψ/μ) ω_max / 2 ≈ 0.08).
double common_step(const std::vector<BeamLevel>& levels) {
  const double cp =
      beam_setup(levels.front().mesh, Integrator::ModifiedEuler, 0).law.p_wave_speed();
  double h = levels.front().shortest;
  for (const BeamLevel& b : levels) h = std::min(h, b.shortest);
  return 0.5 * h / cp;
}

struct LevelsResult {
  std::vector<BeamLevel> levels;
  std::vector<LevelRun> undamped, damped;
};

const LevelsResult& levels_result() {
  static const LevelsResult result = [] {
    LevelsResult r;
    for (int l = 0; l < 3; ++l) r.levels.push_back(load_level(l));
    const double dt = common_step(r.levels);
    for (const BeamLevel& b : r.levels) {
      r.undamped.push_back(run(b.mesh, dt, 0));
      r.damped.push_back(run(b.mesh, dt, 2.0));
    }
    return r;
  }();
  return result;
}

}  // namespace

// Each level alone against its §2.3 band. Breaking it: a stiffness or mass error of 20 % moves
// f1 by 10 % and out of the L2 band; a wrong clamp (free root) drops f1 far below 10 Hz.
TEST(BeamLevelsFrequency, EachLevelAloneIsInItsLockingBand) {
  const LevelsResult& r = levels_result();
  for (int l = 0; l < 3; ++l) {
    const BeamLevel& b = r.levels[l];
    const Oscillation& o = r.undamped[l].o;
    const Band band = f1_band(b.across);
    std::printf(
        "beam L%d: %zu tets, %zu points, shortest edge %.2f mm, mean edge %.2f mm, "
        "%.2f across; f1 %.4f Hz (%.3f of 3-D) over %d periods, static %.4e m; band "
        "[%.3f, %.3f] Hz\n",
        l, b.mesh.tets.size(), b.mesh.points.size(), 1e3 * b.shortest, 1e3 * b.mean_edge, b.across,
        o.frequency, o.frequency / kThreeD, o.periods, o.mean, band.lower, band.upper);
    EXPECT_GE(o.periods, 10) << l;
    EXPECT_GE(o.frequency, band.lower) << l;
    EXPECT_LE(o.frequency, band.upper) << l;
    validation::Check c;
    c.id = "beam_level_f1_L" + std::to_string(l);
    c.group = "Beam levels: first bending frequency";
    c.title = "f1 of bundled beam level L" + std::to_string(l) + " alone (" +
              std::to_string(b.mesh.tets.size()) + " tets), sudden gravity, undamped";
    c.quantity = "f1";
    c.unit = "Hz";
    c.measured = o.frequency;
    c.reference = band.reference;
    c.reference_source = band.source;
    c.lower = band.lower;
    c.upper = band.upper;
    c.tolerance = band.tolerance;
    char note[320];
    std::snprintf(note, sizeof note,
                  "%.2f elements across (tet count vs gmsh h = 5 mm); shortest edge %.2f mm, "
                  "mean edge %.2f mm; dt %.2e s; %d periods; static tip deflection %.4e m = "
                  "%.3f of 3-D",
                  b.across, 1e3 * b.shortest, 1e3 * b.mean_edge, r.undamped[l].dt, o.periods,
                  o.mean, o.mean / kThreeDDeflection);
    c.note = note;
    const validation::Series s = tip_series({&r.undamped[l]}, {"L" + std::to_string(l)});
    validation::record(c, &s);
  }
}

namespace {

// The largest spread (max - min) / mean that f1 values inside the given bands can have: the
// bands box the values, and the spread is largest at a corner of the box.
double widest_spread(const std::vector<Band>& bands) {
  double widest = 0;
  for (unsigned corner = 0; corner < (1u << bands.size()); ++corner) {
    std::vector<double> f;
    for (size_t l = 0; l < bands.size(); ++l)
      f.push_back(corner >> l & 1u ? bands[l].upper : bands[l].lower);
    widest = std::max(widest, relative_spread(f));
  }
  return widest;
}

validation::Check spread_check(const std::string& id, const std::string& title, double measured,
                               double upper) {
  validation::Check c;
  c.id = id;
  c.group = "Beam levels: first bending frequency";
  c.title = title;
  c.quantity = "(max - min) / mean of f1 across levels";
  c.measured = measured;
  c.reference = 0;  // [DDCB01]: "nearly unchanged"
  c.reference_source =
      "[DDCB01] claim (method.md §0.1); bound from the per-level §2.3 bands "
      "(validation.md §2.3 suggested tolerances)";
  c.lower = 0;
  c.upper = upper;
  return c;
}

}  // namespace

// [DDCB01]: "damped vibration modes nearly unchanged across refinement levels". §2.3 says
// what linear tets can do: f1 is +9 % at 4 across and only bounded by an order of magnitude at
// 2 across or coarser, so the spread across these levels is bounded by the widest spread the
// per-level bands allow, not by "nearly unchanged". ψ = 2 Pa.s (beam_adaptive.yaml, φ = 0)
// gives ζ1 ≈ ψ ω1 / (2μ) ≈ 2e-4: the damped frequency is f1 √(1-ζ²), unchanged to 1e-7, so
// the damped spread must equal the undamped one within the period measurement (±0.5 % per
// frequency, ±1 % on the spread). Breaking it: a level whose damping or mass differs (a
// coupling or lumping error) moves its damped frequency off its undamped one.
TEST(BeamLevelsFrequency, DampedModesAcrossLevelsSpreadAsTheLockingBandsAllow) {
  const LevelsResult& r = levels_result();
  std::vector<double> f, fd;
  std::vector<Band> bands;
  for (int l = 0; l < 3; ++l) {
    f.push_back(r.undamped[l].o.frequency);
    fd.push_back(r.damped[l].o.frequency);
    bands.push_back(f1_band(r.levels[l].across));
    EXPECT_GE(r.damped[l].o.periods, 10) << l;
  }
  const double spread = relative_spread(f), damped_spread = relative_spread(fd);
  const double spread12 = relative_spread({f[1], f[2]});
  const double bound = widest_spread(bands), bound12 = widest_spread({bands[1], bands[2]});
  std::printf(
      "f1 across levels L0/L1/L2: %.4f / %.4f / %.4f Hz, damped (psi = 2) %.4f / %.4f / "
      "%.4f Hz; spread %.3f (damped %.3f, bound %.3f); L1-L2 spread %.3f (bound %.3f)\n",
      f[0], f[1], f[2], fd[0], fd[1], fd[2], spread, damped_spread, bound, spread12, bound12);
  EXPECT_LE(spread, bound);
  EXPECT_LE(spread12, bound12);
  EXPECT_NEAR(damped_spread, spread, 0.01);
  for (int l = 0; l < 3; ++l) EXPECT_NEAR(fd[l], f[l], 0.005 * f[l]) << l;

  validation::Check c = spread_check("beam_levels_damped_spread",
                                     "Spread of the damped f1 (psi = 2 Pa.s) across the three "
                                     "bundled beam levels, each alone",
                                     damped_spread, bound);
  c.tolerance =
      "below the widest spread the per-level §2.3 bands allow (L0 has an order-of-"
      "magnitude band only, so this bound is loose)";
  char note[400];
  std::snprintf(note, sizeof note,
                "damped f = %.3f / %.3f / %.3f Hz (L0/L1/L2); undamped spread %.3f. The claim "
                "'nearly unchanged' does not hold for linear tets at 1-4 elements across: §2.3 "
                "gives +9 %% at 4 across and only an order of magnitude at 2 across.",
                fd[0], fd[1], fd[2], spread);
  c.note = note;
  validation::Series s = tip_series({&r.damped[0], &r.damped[1], &r.damped[2]},
                                    {"L0 damped", "L1 damped", "L2 damped"});
  validation::record(c, &s);

  validation::Check c3 = spread_check("beam_levels_f1_spread",
                                      "Spread of f1 across the three bundled beam levels, each "
                                      "alone, undamped",
                                      spread, bound);
  c3.tolerance = c.tolerance;
  std::snprintf(note, sizeof note,
                "f1 = %.3f / %.3f / %.3f Hz (L0/L1/L2); series in "
                "beam_level_f1_L0..L2.csv",
                f[0], f[1], f[2]);
  c3.note = note;
  validation::record(c3);

  validation::Check c12 = spread_check("beam_levels_f1_spread_L1_L2",
                                       "Spread of f1 between beam levels L1 and L2 (the levels "
                                       "§2.3 has rows for), each alone, undamped",
                                       spread12, bound12);
  c12.tolerance = "below the widest spread the L1 and L2 bands of §2.3 allow";
  std::snprintf(note, sizeof note,
                "§2.3's own rows for meshes of these classes (gmsh 10 mm and 5 mm, lumped) "
                "differ by %.3f; the three-level spread is %.3f",
                relative_spread({12.711 * 10.855 / 10.880, 10.855}), spread);
  c12.note = note;
  const validation::Series s12 = tip_series({&r.undamped[1], &r.undamped[2]}, {"L1", "L2"});
  validation::record(c12, &s12);
}
