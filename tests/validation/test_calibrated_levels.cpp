// Issue 16 point 1: each bundled coarse level alone, calibrated with a tensor per tet
// (object.calibration: per_tet, hierarchy/level_calibration.hpp), against its finest level
// alone: the largest displacement under vertical gravity and the first frequency, both of the
// same linear problem (held as the bundled scenarios hold it). Each record is the worst
// |ratio − 1| over the object's coarse levels; the note has every level's ratios, before and
// after the fit. Breaking it: the level-wide fit (orthotropic) leaves the liver's peaks at
// 0.58–0.77 of L3's, the uncalibrated levels at 0.70–0.75; one factor per tet (instead of
// seven) left the beam's L0 tip at 0.85.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "hierarchy/level_calibration.hpp"
#include "scenario/material.hpp"
#include "support/bundled_levels.hpp"
#include "validation/validation_record.hpp"

using namespace mrsim;

namespace {

struct Object {
  const char* name;   // scenarios/meshes/<name>_L<k>.vtu
  int levels;
  double E, nu;       // as the bundled scenarios give them
  std::function<bool(const Vec3&)> held;
  double upper;       // the band asserted on the worst ratio
  const char* tolerance;
};

// The worst |peak z − 1| and |f1 − 1| over the coarse levels, and a note of every ratio.
std::pair<double, std::string> worst_ratio(const Object& o) {
  const test_support::BundledLevels b = test_support::bundled_levels(o.name, o.levels, o.held);
  const scenario::LameParameters lame = scenario::lame_from_engineering({o.E, o.nu});
  MaterialLaw law;
  law.lambda = lame.lambda;
  law.mu = lame.mu;
  const auto c = calibrate_levels(b.pointers(), law, b.fixed, CalibrationKind::PerTet);
  double worst = 0;
  std::string note;
  char line[200];
  for (int l = 0; l + 1 < o.levels; ++l) {
    const double peak = c[l].peak_after[2], f1 = c[l].frequency_after[0];
    worst = std::max({worst, std::abs(peak - 1), std::abs(f1 - 1)});
    std::snprintf(line, sizeof line, "%sL%d (%zu tets): peak z %.3f (uncalibrated %.3f), f1 %.3f (%.3f)",
                  l ? "; " : "", l, b.meshes[l].tets.size(), peak, c[l].peak_before[2], f1,
                  c[l].frequency_before[0]);
    note += line;
  }
  return {worst, note};
}

void check_object(const Object& o) {
  const auto [worst, note] = worst_ratio(o);
  std::printf("%s: worst %.4f; %s\n", o.name, worst, note.c_str());
  validation::Check c;
  c.id = std::string("levels_alone_per_tet_") + o.name;
  c.group = "Levels alone (calibrated)";
  c.title = std::string("Each coarse ") + o.name +
            " level alone with per-tet calibration vs its finest level alone: largest "
            "displacement under vertical gravity and f1";
  c.quantity = "worst |ratio - 1| over the coarse levels";
  c.measured = worst;
  c.reference = 0;
  c.reference_source = "the finest level alone, same linear problem (issue 16 point 1)";
  c.lower = 0;
  c.upper = o.upper;
  c.tolerance = o.tolerance;
  c.note = note;
  validation::record(c);
  EXPECT_LE(worst, o.upper);
}

TEST(CalibratedLevels, LiverLevelsAloneWithinFivePercentOfTheFinest) {
  check_object({"liver", 4, 3e4, 0.4, [](const Vec3& p) { return p.z() <= 0.1; }, 0.05,
                "issue 16 asks within 5 %"});
}

TEST(CalibratedLevels, LittleManLevelsAloneWithinFivePercentOfTheFinest) {
  check_object({"little_man", 3, 2e4, 0.4, [](const Vec3& p) { return p.z() <= 0.008; }, 0.05,
                "issue 16 asks within 5 %"});
}

TEST(CalibratedLevels, BeamLevelsAloneWithinFivePercentOfTheFinest) {
  // L0 is one tet across; with seven factors per tet its tip and f1 follow L2's too.
  check_object({"beam", 3, 1e6, 0.3, [](const Vec3& p) { return std::abs(p.x()) <= 1e-3; }, 0.05,
                "issue 16 asks within 5 %"});
}

}  // namespace
