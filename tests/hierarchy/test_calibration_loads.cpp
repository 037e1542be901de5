// The local loads of the per-tet calibration (hierarchy/calibration_loads.hpp): patches of free
// boundary points spread over the finest level's surface, each a unit force pushing inwards,
// and their transfer to a coarser level by barycentric weights, which keeps the force and its
// moment (the weights reproduce positions), as the hierarchy's ghost force transfer does.
#include <gtest/gtest.h>

#include <set>

#include "hierarchy/calibration_loads.hpp"
#include "mesh/boundary_faces.hpp"
#include "mesh/box_mesh.hpp"

namespace mrsim {
namespace {

std::vector<std::uint8_t> held_at_x0(const TetMesh& m) {
  std::vector<std::uint8_t> f;
  for (const Vec3& p : m.points) f.push_back(p.x() < 1e-9 ? 1 : 0);
  return f;
}

TEST(CalibrationLoads, PatchesOfFreeBoundaryPointsPushingInwards) {
  const TetMesh fine = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), 20, 4, 4);
  const std::vector<std::uint8_t> held = held_at_x0(fine);
  std::set<int> boundary;
  for (const Face& f : boundary_faces(fine)) boundary.insert(f.begin(), f.end());
  const std::vector<LocalLoad> loads = local_loads(fine, held, 12, 0.006);
  ASSERT_EQ(loads.size(), 12u);
  const Vec3 centre(0.05, 0.01, 0.01);
  std::set<int> centres;
  for (const LocalLoad& l : loads) {
    ASSERT_FALSE(l.points.empty());
    Vec3 total = Vec3::Zero(), where = Vec3::Zero();
    for (int i : l.points) {
      EXPECT_TRUE(boundary.count(i)) << i;
      EXPECT_FALSE(held[i]) << i;
      total += l.force;
      where += fine.points[i] / static_cast<double>(l.points.size());
    }
    EXPECT_NEAR(total.norm(), 1.0, 1e-12);
    EXPECT_LT(total.dot(where - centre), 0.0) << "pushes inwards";
    centres.insert(l.points.front());
  }
  EXPECT_GE(centres.size(), 10u) << "spread over the surface";
}

TEST(CalibrationLoads, ACoarseLevelReceivesTheForceAndItsMoment) {
  const TetMesh fine = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), 20, 4, 4);
  const TetMesh coarse = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.02, 0.02), 5, 1, 1);
  const std::vector<LocalLoad> loads = local_loads(fine, held_at_x0(fine), 12, 0.006);
  const std::vector<Eigen::VectorXd> own = level_loads(loads, fine, fine);
  const std::vector<Eigen::VectorXd> passed = level_loads(loads, fine, coarse);
  ASSERT_EQ(passed.size(), loads.size());
  for (std::size_t k = 0; k < loads.size(); ++k) {
    const Eigen::VectorXd& f = own[k];
    const Eigen::VectorXd& g = passed[k];
    ASSERT_EQ(g.size(), 3 * static_cast<Eigen::Index>(coarse.points.size()));
    auto resultant = [](const Eigen::VectorXd& v, const TetMesh& m) {
      Vec3 F = Vec3::Zero(), T = Vec3::Zero();
      for (std::size_t i = 0; i < m.points.size(); ++i) {
        const Vec3 fi = v.segment<3>(3 * static_cast<Eigen::Index>(i));
        F += fi;
        T += m.points[i].cross(fi);
      }
      return std::make_pair(F, T);
    };
    const auto [F1, T1] = resultant(f, fine);
    const auto [F2, T2] = resultant(g, coarse);
    EXPECT_NEAR((F1 - F2).norm(), 0.0, 1e-12);
    EXPECT_NEAR((T1 - T2).norm(), 0.0, 1e-12);
    EXPECT_NEAR(F1.norm(), 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace mrsim
