// The levels of a scenario are one object, coarse to fine (issue 18 defect 10): a beam level
// beside a liver level, levels listed fine to coarse, or one mesh twice are input errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "io/temp_dir.hpp"
#include "mesh/box_mesh.hpp"
#include "simulation/level_consistency.hpp"

namespace mrsim {
namespace {

namespace fs = std::filesystem;

// A scenario whose levels name `files` (created empty: only their identity matters here).
Scenario with_files(const std::vector<std::string>& files) {
  static const mrsim::test::TempDir scratch;  // removed when the tests end
  const fs::path& dir = scratch.path();
  Scenario sc;
  for (const std::string& f : files) {
    std::ofstream(dir / f) << "";
    sc.levels.push_back({dir / f});
  }
  return sc;
}

std::string message_of(const Scenario& sc, const std::vector<const TetMesh*>& meshes) {
  try {
    check_level_consistency(sc, meshes);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const Vec3 kMin(0, 0, 0), kMax(0.1, 0.02, 0.02);

TEST(LevelConsistency, OneObjectCoarseToFineIsAccepted) {
  const TetMesh coarse = make_box_mesh(kMin, kMax, 5, 1, 1),
                fine = make_box_mesh(kMin, kMax, 20, 4, 4);
  EXPECT_EQ(message_of(with_files({"a.vtu", "b.vtu"}), {&coarse, &fine}), "");
}

TEST(LevelConsistency, FineToCoarseIsRefused) {
  const TetMesh coarse = make_box_mesh(kMin, kMax, 5, 1, 1),
                fine = make_box_mesh(kMin, kMax, 20, 4, 4);
  EXPECT_NE(message_of(with_files({"a.vtu", "b.vtu"}), {&fine, &coarse})
                .find("object.levels[1] has 30 tets, not more than object.levels[0] (1920): list "
                      "the levels coarse to fine"),
            std::string::npos);
}

TEST(LevelConsistency, TheSameMeshTwiceIsRefused) {
  const TetMesh coarse = make_box_mesh(kMin, kMax, 5, 1, 1),
                fine = make_box_mesh(kMin, kMax, 20, 4, 4);
  EXPECT_NE(message_of(with_files({"a.vtu", "a.vtu"}), {&coarse, &fine})
                .find("object.levels[1]: the same mesh as object.levels[0]"),
            std::string::npos);
}

TEST(LevelConsistency, AnotherObjectIsRefusedAndQuarterOffIsTheLimit) {
  const TetMesh fine = make_box_mesh(kMin, kMax, 20, 4, 4);
  const TetMesh bigger = make_box_mesh(kMin, Vec3(0.13, 0.02, 0.02), 5, 1, 1);  // +30 % volume
  const TetMesh close = make_box_mesh(kMin, Vec3(0.12, 0.02, 0.02), 5, 1, 1);   // +20 %
  const TetMesh moved = make_box_mesh(Vec3(0.03, 0, 0), Vec3(0.13, 0.02, 0.02), 5, 1, 1);
  const Scenario sc = with_files({"a.vtu", "b.vtu"});
  EXPECT_NE(message_of(sc, {&bigger, &fine})
                .find("object.levels[0] is not the object of the "
                      "finest level object.levels[1]"),
            std::string::npos);
  EXPECT_EQ(message_of(sc, {&close, &fine}), "");
  EXPECT_NE(message_of(sc, {&moved, &fine}).find("bounding-box centres 0.03 m apart"),
            std::string::npos);  // same volume, 0.03 m off a 0.1039 m diagonal
}

}  // namespace
}  // namespace mrsim
