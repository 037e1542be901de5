#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "hierarchy/closest_point.hpp"
#include "hierarchy/tet_locator.hpp"
#include "mesh/box_mesh.hpp"
#include "mesh/tet_neighbours.hpp"

using namespace mrsim;

namespace {

TetMesh jittered_box() {
  TetMesh m = make_box_mesh(Vec3(0, 0, 0), Vec3(1, 0.6, 0.4), 10, 6, 4);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> d(-0.02, 0.02);
  for (Vec3& p : m.points)
    if (p.x() > 0 && p.x() < 1 && p.y() > 0 && p.y() < 0.6 && p.z() > 0 && p.z() < 0.4)
      p += Vec3(d(rng), d(rng), d(rng));
  return m;
}

double brute_force_distance(const TetMesh& m, const TetLocator& loc, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) {
    const auto b = loc.barycentric(t, p);
    if (*std::min_element(b.begin(), b.end()) >= 0) return 0;
    for (const auto& f : kFaces)
      best = std::min(best, (p - closest_point_on_triangle(p, m.points[m.tets[t][f[0]]],
                                                           m.points[m.tets[t][f[1]]],
                                                           m.points[m.tets[t][f[2]]]))
                                .norm());
  }
  return best;
}

}  // namespace

TEST(TetLocator, FindsTheContainingTetAndReproducesThePoint) {
  const TetMesh m = jittered_box();
  const TetLocator loc(m);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> x(0, 1), y(0, 0.6), z(0, 0.4);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 p(x(rng), y(rng), z(rng));
    const TetLocation l = loc.locate(p);
    ASSERT_GE(l.tet, 0);
    EXPECT_TRUE(l.inside());
    EXPECT_GE(*std::min_element(l.bary.begin(), l.bary.end()), -1e-12);
    Vec3 q = Vec3::Zero();
    for (int a = 0; a < 4; ++a) q += l.bary[a] * m.points[m.tets[l.tet][a]];
    EXPECT_LT((q - p).norm(), 1e-12);
  }
}

TEST(TetLocator, OutsidePointsGetTheNearestTetWithSignedCoordinates) {
  const TetMesh m = jittered_box();
  const TetLocator loc(m);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> d(-0.3, 1.3);
  int outside = 0;
  for (int k = 0; k < 300; ++k) {
    const Vec3 p(d(rng), d(rng) * 0.6, d(rng) * 0.4);
    const TetLocation l = loc.locate(p);
    const double ref = brute_force_distance(m, loc, p);
    EXPECT_NEAR(l.distance, ref, 1e-12);
    if (ref > 0) {
      ++outside;
      EXPECT_LT(*std::min_element(l.bary.begin(), l.bary.end()), 0.0);
      Vec3 q = Vec3::Zero();  // signed coordinates still reproduce the point (extrapolation)
      for (int a = 0; a < 4; ++a) q += l.bary[a] * m.points[m.tets[l.tet][a]];
      EXPECT_LT((q - p).norm(), 1e-10);
    }
  }
  EXPECT_GT(outside, 100);
}

// containing() (and locate() inside the mesh, which uses it) against every tet: the tet with the
// largest smallest barycentric coordinate among those holding the point, ties to the lowest
// index; -1 outside (level ownership relies on it). The jittered box is not convex, so points
// between its dents are outside too. Vertices are included: points on shared faces.
TEST(TetLocator, ContainingIsTheBestHoldingTetAndMinusOneOutside) {
  const TetMesh m = jittered_box();
  const TetLocator loc(m);
  const auto neighbours = tet_neighbours(m);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(-0.1, 1.1);
  int inside = 0, outside = 0, previous = -1;
  auto check = [&](const Vec3& p) {
    int best = -1;
    double best_min = 0;
    for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) {
      const auto b = loc.barycentric(t, p);
      const double low = *std::min_element(b.begin(), b.end());
      if (low >= -1e-12 && (best < 0 || low > best_min)) best = t, best_min = low;
    }
    EXPECT_EQ(loc.containing(p), best) << p.transpose();
    // A hint changes the work, never the answer: the right tet, a neighbour's, any, none;
    // nor does a walk from it across the faces (far hints walk from p's grid cell).
    const int any = static_cast<int>(rng() % m.tets.size());
    for (const int hint : {best, previous, any, -1}) {
      EXPECT_EQ(loc.containing(p, hint), best) << p.transpose() << ", hint " << hint;
      EXPECT_EQ(loc.containing(p, hint, &neighbours), best) << p.transpose() << ", walk " << hint;
    }
    previous = best;
    EXPECT_EQ(loc.locate(p).inside(), best >= 0) << p.transpose();
    if (best >= 0) {
      EXPECT_EQ(loc.locate(p).tet, best) << p.transpose();
    }
    ++(best >= 0 ? inside : outside);
  };
  for (int k = 0; k < 3000; ++k) check(Vec3(d(rng), d(rng) * 0.6, d(rng) * 0.4));
  for (const Vec3& p : m.points) check(p);
  EXPECT_GT(inside, 2000);
  EXPECT_GT(outside, 500);
}

// Outside the mesh, locate() searches rings of grid cells, skips cells farther than its best so
// far and measures each tet once however many cells it overlaps; none of that may change the
// answer: the nearest tet by the same distance, ties to the lowest index, bit for bit. The box
// has a notch cut into its top, as independent meshes of one object have dents in each other's
// hulls: a point in the notch lies in grid cells that hold no tet, so the ring search decides.
TEST(TetLocator, OutsideAnswerIsTheNearestTetOfAllTiesToTheLowestIndex) {
  TetMesh m = jittered_box();
  std::vector<Tet> kept;
  for (const Tet& t : m.tets) {
    Vec3 c = Vec3::Zero();
    for (int v : t) c += m.points[v] / 4;
    const bool notch = c.x() > 0.25 && c.x() < 0.75 && c.y() > 0.1 && c.y() < 0.5 && c.z() > 0.1;
    if (!notch) kept.push_back(t);
  }
  m.tets = kept;
  const TetLocator loc(m);
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  auto nearest = [&](const Vec3& p, double& distance) {
    int best = -1;
    for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) {
      double d = std::numeric_limits<double>::infinity();
      for (const auto& f : kFaces)
        d = std::min(d, (p - closest_point_on_triangle(p, m.points[m.tets[t][f[0]]],
                                                       m.points[m.tets[t][f[1]]],
                                                       m.points[m.tets[t][f[2]]]))
                            .norm());
      if (best < 0 || d < distance) best = t, distance = d;
    }
    return best;
  };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(0.2, 0.8), y(0.05, 0.55), z(0.05, 0.45),
      u(-0.2, 1.2);
  int in_notch = 0, checked = 0;
  for (int k = 0; k < 1500; ++k) {
    // Two thirds in and above the notch, the rest anywhere around the box.
    const Vec3 p = k % 3 ? Vec3(x(rng), y(rng), z(rng))
                         : Vec3(u(rng), 0.6 * u(rng), 0.4 * u(rng));
    if (loc.containing(p) >= 0) continue;
    double ref = 0;
    const int t = nearest(p, ref);
    const TetLocation l = loc.locate(p);
    ASSERT_EQ(l.tet, t) << p.transpose();
    EXPECT_EQ(l.distance, ref) << p.transpose();
    ++checked;
    in_notch += k % 3 != 0;
  }
  EXPECT_GT(in_notch, 600);
  EXPECT_GT(checked, 900);
}
