// Face neighbours of tets: symmetric, sharing exactly the face opposite the vertex they are
// listed under, and -1 on exactly the boundary faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "mesh/boundary_faces.hpp"
#include "mesh/box_mesh.hpp"
#include "mesh/tet_neighbours.hpp"

namespace mrsim {
namespace {

TEST(TetNeighbours, SymmetricAcrossTheOppositeFaceAndMissingOnTheBoundaryOnly) {
  TetMesh m = make_box_mesh(Vec3(0, 0, 0), Vec3(1, 0.6, 0.4), 6, 4, 3);
  // Holes and a shuffled order: inner faces become boundary, nothing depends on tet order.
  std::vector<Tet> kept;
  for (std::size_t t = 0; t < m.tets.size(); ++t)
    if (t % 9 != 4) kept.push_back(m.tets[t]);
  std::shuffle(kept.begin(), kept.end(), std::mt19937(7));
  m.tets = kept;
  const auto nbr = tet_neighbours(m);
  ASSERT_EQ(nbr.size(), m.tets.size());
  std::size_t open = 0;
  for (std::size_t t = 0; t < m.tets.size(); ++t)
    for (int k = 0; k < 4; ++k) {
      const int u = nbr[t][k];
      if (u < 0) {
        ++open;
        continue;
      }
      // u lists t back, and the two share the three vertices of t other than vertex k.
      const auto& back = nbr[u];
      EXPECT_EQ(std::count(back.begin(), back.end(), static_cast<int>(t)), 1);
      for (int a = 0; a < 4; ++a) {
        const bool shared = std::count(m.tets[u].begin(), m.tets[u].end(), m.tets[t][a]) == 1;
        EXPECT_EQ(shared, a != k) << t << " " << k << " " << a;
      }
    }
  EXPECT_EQ(open, boundary_faces(m).size());
  EXPECT_GT(open, 2u * 2 * (6 * 4 + 6 * 3 + 4 * 3));  // the holes opened inner faces
}

}  // namespace
}  // namespace mrsim
