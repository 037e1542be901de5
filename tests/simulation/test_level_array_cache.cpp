// A level's adjacency, Laplacian weights and energy bounds kept between runs
// (simulation/level_array_cache.hpp): a warm build takes them and is the same model, bit for bit;
// what is stored is what is used; a record that does not fit the mesh is said, ignored and
// written again.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "simulation/cache_folder.hpp"
#include "simulation/level_array_cache.hpp"
#include "simulation/small_level.hpp"
#include "simulation/spectrum_cache.hpp"
#include "support/same_bits.hpp"

using namespace mrsim;

namespace {

TetMesh box() { return test::small_box(); }
MaterialLaw law() { return test::damped_law(); }
using test::same_bits;

void expect_same_model(const LevelModel& a, const LevelModel& b) {
  EXPECT_EQ(a.adj.nbr_start, b.adj.nbr_start);
  EXPECT_EQ(a.adj.nbr, b.adj.nbr);
  EXPECT_EQ(a.adj.inc_start, b.adj.inc_start);
  EXPECT_EQ(a.adj.inc_tet, b.adj.inc_tet);
  EXPECT_EQ(a.adj.inc_local, b.adj.inc_local);
  EXPECT_TRUE(same_bits(a.laplacian_w, b.laplacian_w));
  EXPECT_TRUE(same_bits(a.bounds.stiffness, b.bounds.stiffness));
  EXPECT_TRUE(same_bits(a.bounds.damping, b.bounds.damping));
  EXPECT_TRUE(same_bits(a.star, b.star));
  EXPECT_TRUE(same_bits(a.mass, b.mass));
  EXPECT_TRUE(same_bits(a.mean_edge, b.mean_edge));
  EXPECT_TRUE(same_bits(a.min_edge, b.min_edge));
}

}  // namespace

TEST(LevelArrayCache, AWarmBuildTakesTheArraysAndIsTheSameModel) {
  CacheFolder folder("level_arrays");
  const TetMesh mesh = box();
  bool reused = true;
  const LevelModel cold = cached_level_model(mesh, law(), false, {}, &reused);
  EXPECT_FALSE(reused);
  ASSERT_EQ(folder.files("level_arrays").size(), 1u);
  const LevelModel warm = cached_level_model(mesh, law(), false, {}, &reused);
  EXPECT_TRUE(reused);
  expect_same_model(cold, warm);
  // Computed with every input as a warm build gets them: the same arrays again.
  expect_same_model(build_level_model(mesh, law()), warm);
  // A law the arrays do not hold the bounds of is another record.
  MaterialLaw stiffer = law();
  stiffer.mu *= 2;
  cached_level_model(mesh, stiffer, false, {});
  EXPECT_EQ(folder.files("level_arrays").size(), 2u);
}

TEST(LevelArrayCache, TheArraysStoredAreTheOnesAWarmBuildUses) {
  CacheFolder folder("level_arrays");
  const TetMesh mesh = box();
  LevelModel m = cached_level_model(mesh, law(), false, {});
  for (double& b : m.bounds.stiffness) b *= 2;
  write_level_arrays(spectrum_key(mesh, law(), false, {}), m);
  const LevelModel warm = cached_level_model(mesh, law(), false, {});
  EXPECT_TRUE(same_bits(warm.bounds.stiffness, m.bounds.stiffness));
  EXPECT_GT(warm.star[0].stiffness, build_level_model(mesh, law()).star[0].stiffness);
}

TEST(LevelArrayCache, ARecordThatDoesNotFitTheMeshIsSaidIgnoredAndWrittenAgain) {
  CacheFolder folder("level_arrays");
  const TetMesh mesh = box();
  const LevelModel fresh = cached_level_model(mesh, law(), false, {});
  const std::string key = spectrum_key(mesh, law(), false, {});
  const std::vector<std::pair<const char*, std::function<void(LevelModel&)>>> damages = {
      {"a neighbour out of the level", [](LevelModel& m) { m.adj.nbr[3] = 1 << 20; }},
      {"neighbours not ascending", [](LevelModel& m) { std::swap(m.adj.nbr[0], m.adj.nbr[1]); }},
      {"a tet that is not the point's", [](LevelModel& m) { m.adj.inc_local[0] ^= 1; }},
      {"rows that do not add up", [](LevelModel& m) { m.adj.inc_start[1] += 1; }},
      {"one weight short", [](LevelModel& m) { m.laplacian_w.pop_back(); }},
      {"a bound that is not a number",
       [](LevelModel& m) { m.bounds.damping[2] = std::numeric_limits<double>::quiet_NaN(); }},
      {"a negative bound", [](LevelModel& m) { m.bounds.stiffness[1] = -1; }},
  };
  for (const auto& [what, damage] : damages) {
    LevelModel damaged = fresh;
    damage(damaged);
    write_level_arrays(key, damaged);
    ::testing::internal::CaptureStderr();
    const LevelModel m = cached_level_model(mesh, law(), false, {});
    const std::string said = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(said.find("ignored the level arrays cache"), std::string::npos)
        << what << ": " << said;
    expect_same_model(m, fresh);
    ::testing::internal::CaptureStderr();
    cached_level_model(mesh, law(), false, {});
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << "written again after " << what;
    EXPECT_TRUE(read_level_arrays(key, mesh).has_value()) << what;
  }
}
