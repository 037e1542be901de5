// Calibrated coarse levels (hierarchy/level_calibration.hpp): each bundled coarse level alone,
// with its fitted orthotropic tensor, answers like its finest level; with a factor per tet on
// top (CalibrationKind::PerTet) its largest displacement too.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "core/error.hpp"
#include "hierarchy/level_calibration.hpp"
#include "mesh/box_mesh.hpp"
#include "support/bundled_levels.hpp"

namespace mrsim {
namespace {

using Bundled = test_support::BundledLevels;
using test_support::bundled_levels;

MaterialLaw law(double E, double nu) {
  MaterialLaw m;
  m.lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  m.mu = E / (2 * (1 + nu));
  return m;
}

void print(const std::string& name, const std::vector<LevelCalibration>& c) {
  for (size_t l = 0; l + 1 < c.size(); ++l) {
    std::printf("%s L%zu (%d iterations) scales", name.c_str(), l, c[l].iterations);
    for (double s : c[l].scales.components()) std::printf(" %.3f", s);
    std::printf("\n  sag before/after:");
    for (size_t d = 0; d < c[l].sag_before.size(); ++d)
      std::printf(" %.3f/%.3f", c[l].sag_before[d], c[l].sag_after[d]);
    std::printf("\n  peak before/after:");
    for (size_t d = 0; d < c[l].peak_before.size(); ++d)
      std::printf(" %.3f/%.3f", c[l].peak_before[d], c[l].peak_after[d]);
    std::printf("\n  frequency before/after:");
    for (size_t k = 0; k < c[l].frequency_before.size(); ++k)
      std::printf(" %.3f/%.3f", c[l].frequency_before[k], c[l].frequency_after[k]);
    std::printf("\n");
  }
}

// Every coarse level, after the fit: sags within `sag_band` and f1 within `f1_band` of the
// finest level's; `before` asserts the fit had something to correct.
void expect_calibrated(const std::vector<LevelCalibration>& c, double sag_band, double f1_band) {
  for (size_t l = 0; l + 1 < c.size(); ++l) {
    for (double r : c[l].sag_after) EXPECT_NEAR(r, 1.0, sag_band) << "level " << l;
    EXPECT_NEAR(c[l].frequency_after[0], 1.0, f1_band) << "level " << l;
    EXPECT_FALSE(c[l].scales.isotropic());
  }
  EXPECT_TRUE(c.back().scales.isotropic());
  EXPECT_TRUE(c.back().sag_after.empty());
}

double worst(const std::vector<double>& ratios) {
  double w = 0;
  for (double r : ratios) w = std::max(w, std::abs(std::log(r)));
  return w;
}

TEST(LevelCalibration, LiverLevelsAloneAnswerLikeTheFinest) {
  const Bundled b = bundled_levels("liver", 4, [](const Vec3& p) { return p.z() <= 0.1; });
  const auto c = calibrate_levels(b.pointers(), law(3e4, 0.4), b.fixed);
  print("liver", c);
  // Measured: sags 1.02-1.06 and f1 1.01-1.06 of L3's (before: sags up to 1.46, f2 0.85).
  expect_calibrated(c, 0.07, 0.065);
  EXPECT_GT(c[0].sag_before[0], 1.3);
  for (int l = 0; l < 3; ++l) EXPECT_LT(worst(c[l].sag_after), worst(c[l].sag_before) + 1e-9);
}

TEST(LevelCalibration, BeamLevelsAloneAnswerLikeTheFinest) {
  const Bundled b = bundled_levels("beam", 3, [](const Vec3& p) { return std::abs(p.x()) <= 1e-3; });
  const auto c = calibrate_levels(b.pointers(), law(1e6, 0.3), b.fixed);
  print("beam", c);
  // Linear tets one or two across lock in bending: L0 sagged 0.23-0.36 of L2 and rang at
  // 1.76 x its f1. Calibrated: sags within 6 %, and the levels' f1 within 5 % of each other.
  EXPECT_LT(c[0].sag_before[2], 0.3);
  EXPECT_GT(c[0].frequency_before[0], 1.7);
  expect_calibrated(c, 0.06, 0.05);
  double lo = 1, hi = 1;
  for (const LevelCalibration& l : c)
    if (!l.frequency_after.empty()) {
      lo = std::min(lo, l.frequency_after[0]);
      hi = std::max(hi, l.frequency_after[0]);
    }
  EXPECT_LE(hi / lo, 1.05) << "f1 spread of the calibrated beam levels";
}

TEST(LevelCalibration, LittleManLevelsAloneAnswerLikeTheFinest) {
  const Bundled b = bundled_levels("little_man", 3, [](const Vec3& p) { return p.z() <= 0.008; });
  const auto c = calibrate_levels(b.pointers(), law(2e4, 0.4), b.fixed);
  print("little_man", c);
  expect_calibrated(c, 0.05, 0.05);
}

// PerTet: every coarse level's factors, seven per tet, positive, no component of any tet's
// tensor above 5; peaks (every direction) and f1, issue 16's measures, within `band` of the
// finest level's, and the sags, the fit's own, within `sag_band`.
void expect_per_tet(const Bundled& b, const std::vector<LevelCalibration>& c, double band,
                    double sag_band) {
  for (size_t l = 0; l + 1 < c.size(); ++l) {
    ASSERT_EQ(c[l].tet_tensors.size(), b.meshes[l].tets.size()) << "level " << l;
    const auto s = c[l].scales.components();
    for (const auto& q : c[l].tet_tensors)
      for (int j = 0; j < 7; ++j) {
        EXPECT_GT(q[j], 0.0);
        EXPECT_LE(q[j] * s[j], 5.0 * (1 + 1e-12)) << "level " << l << ", component " << j;
      }
    for (double r : c[l].sag_after) EXPECT_NEAR(r, 1.0, sag_band) << "sag, level " << l;
    for (double r : c[l].peak_after) EXPECT_NEAR(r, 1.0, band) << "peak, level " << l;
    EXPECT_NEAR(c[l].frequency_after[0], 1.0, band) << "f1, level " << l;
  }
  EXPECT_TRUE(c.back().tet_tensors.empty());
}

// The liver's and the little man's per-tet fits are validation records
// (tests/validation/test_calibrated_levels.cpp); the beam's, quick, checks the factors here.
TEST(LevelCalibration, PerTetBeamLevelsAlone) {
  // Both coarse levels meet issue 16's targets, L0 one tet across too (measured: peaks
  // 0.97-1.03, f1 0.96, sags 0.98-1.07; one factor per tet gave its tip 0.85, the level-wide
  // tensor 0.68).
  const Bundled b = bundled_levels("beam", 3, [](const Vec3& p) { return std::abs(p.x()) <= 1e-3; });
  const auto c = calibrate_levels(b.pointers(), law(1e6, 0.3), b.fixed, CalibrationKind::PerTet);
  print("beam per tet", c);
  expect_per_tet(b, c, 0.05, 0.08);
  // The local loads: L1 takes them about as L2 does (measured 0.93-1.06, from 0.26-0.68); L0,
  // one tet across, cannot without losing its sags or f1, so they are reported, not fitted.
  ASSERT_EQ(c[1].local_after.size(), 12u);
  EXPECT_TRUE(c[1].local_fitted);
  for (double r : c[1].local_after) EXPECT_NEAR(r, 1.0, 0.08);
  EXPECT_LT(*std::min_element(c[1].local_before.begin(), c[1].local_before.end()), 0.5);
  EXPECT_FALSE(c[0].local_fitted);
  EXPECT_EQ(c[0].local_after.size(), 12u);
  EXPECT_LE(std::max({c[0].frequency_after[0], c[1].frequency_after[0], 1.0}) /
                std::min({c[0].frequency_after[0], c[1].frequency_after[0], 1.0}),
            1.05)
      << "f1 spread of the per-tet beam levels";
}

// The per-tet fit's dense products are large (rows × 7 N): Eigen would split them over the
// OpenMP threads with thread-count-dependent blockings (EIGEN_DONT_PARALLELIZE, src/CMakeLists);
// the factors must not depend on the thread count, as no result of a run may.
TEST(LevelCalibration, PerTetFitIsTheSameOnAnyThreadCount) {
  const Bundled b = bundled_levels("beam", 3, [](const Vec3& p) { return std::abs(p.x()) <= 1e-3; });
  const int threads = omp_get_max_threads();
  std::vector<std::vector<LevelCalibration>> fits;
  for (const int n : {1, 2}) {
    omp_set_num_threads(n);
    fits.push_back(calibrate_levels(b.pointers(), law(1e6, 0.3), b.fixed, CalibrationKind::PerTet));
  }
  omp_set_num_threads(threads);
  for (std::size_t l = 0; l + 1 < fits[0].size(); ++l) {
    EXPECT_EQ(fits[0][l].tet_tensors, fits[1][l].tet_tensors) << "level " << l;
    EXPECT_EQ(fits[0][l].scales.components(), fits[1][l].scales.components()) << "level " << l;
  }
}

TEST(LevelCalibration, AFreeBodyIsFittedOnItsFrequencies) {
  std::vector<TetMesh> meshes = {make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), 5, 1, 1),
                                 make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), 20, 4, 4)};
  const auto c = calibrate_levels({&meshes[0], &meshes[1]}, law(1e5, 0.3), {});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_TRUE(c[0].sag_after.empty());  // nothing holds it: no sag
  ASSERT_EQ(c[0].frequency_after.size(), 6u);
  EXPECT_GT(c[0].frequency_before[0], 1.3);  // the 1-cell-thick bar is far too stiff
  EXPECT_NEAR(c[0].frequency_after[0], 1.0, 0.05);
}

TEST(LevelCalibration, LevelsHeldAtTooFewPointsAreAnInputError) {
  std::vector<TetMesh> meshes = {make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), 5, 1, 1),
                                 make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), 10, 2, 2)};
  std::vector<std::vector<std::uint8_t>> fixed = {
      std::vector<std::uint8_t>(meshes[0].points.size(), 0),
      std::vector<std::uint8_t>(meshes[1].points.size(), 0)};
  fixed[0][0] = fixed[1][0] = 1;
  EXPECT_THROW(calibrate_levels({&meshes[0], &meshes[1]}, law(1e5, 0.3), fixed), InputError);
  // Held along one edge (x axis): collinear, the level turns about it.
  for (size_t l = 0; l < 2; ++l)
    for (size_t i = 0; i < meshes[l].points.size(); ++i)
      fixed[l][i] = meshes[l].points[i].y() < 1e-9 && meshes[l].points[i].z() < 1e-9;
  try {
    calibrate_levels({&meshes[0], &meshes[1]}, law(1e5, 0.3), fixed);
    ADD_FAILURE() << "a level held along a line was calibrated";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("do not hold it"), std::string::npos) << e.what();
  }
  fixed[0].assign(fixed[0].size(), 0);  // held on the fine level only
  fixed[1].assign(fixed[1].size(), 1);
  EXPECT_THROW(calibrate_levels({&meshes[0], &meshes[1]}, law(1e5, 0.3), fixed), InputError);
}

}  // namespace
}  // namespace mrsim
