// A level model built from spectra measured before (level_spectra(), what the spectrum
// cache keeps) is the model that measured them, bit for bit, without the Lanczos runs and, where
// nothing else needs them, without K and D.
#include <gtest/gtest.h>


#include "mesh/box_mesh.hpp"
#include "physics/level_model.hpp"
#include "support/same_bits.hpp"

using namespace mrsim;

namespace {

// Cells graded towards the held face x = 0, so that no two points see the same star.
TetMesh graded_box() {
  TetMesh mesh = make_box_mesh(Vec3(0, 0, 0), Vec3(0.1, 0.04, 0.03), 6, 3, 3);
  for (Vec3& p : mesh.points) p.x() = 0.1 * std::pow(p.x() / 0.1, 1.7);
  return mesh;
}

std::vector<std::uint8_t> held_face(const TetMesh& mesh) {
  std::vector<std::uint8_t> held(mesh.points.size(), 0);
  for (size_t i = 0; i < held.size(); ++i) held[i] = mesh.points[i].x() < 1e-9 ? 1 : 0;
  return held;
}

MaterialLaw damped(StrainMeasure strain) {
  MaterialLaw law;
  law.strain = strain;
  law.lambda = 4.0e4;
  law.mu = 1.0e4;
  law.psi = 5;
  law.phi = 0.5;
  return law;
}

using test::same_bits;

void expect_same_scales(const LevelModel& a, const LevelModel& b) {
  for (auto [x, y] : {std::pair{a.stiffness_spectrum, b.stiffness_spectrum},
                      std::pair{a.damping_spectrum, b.damping_spectrum},
                      std::pair{a.filter_spectrum, b.filter_spectrum}}) {
    EXPECT_TRUE(same_bits(x.eigenvalue, y.eigenvalue));
    EXPECT_TRUE(same_bits(x.star_max, y.star_max));
    EXPECT_TRUE(same_bits(x.scale, y.scale));
  }
  EXPECT_TRUE(same_bits(a.step_damping_scale, b.step_damping_scale));
  EXPECT_TRUE(same_bits(a.time_level_damping_scale, b.time_level_damping_scale));
  EXPECT_TRUE(same_bits(a.laplacian_w, b.laplacian_w));
}

}  // namespace

TEST(LevelModel, KnownSpectraGiveTheMeasuredModel) {
  const TetMesh mesh = graded_box();
  const std::vector<std::uint8_t> held = held_face(mesh);
  for (StrainMeasure strain : {StrainMeasure::GreenLagrange, StrainMeasure::Cauchy})
    for (bool semi : {false, true}) {
      SCOPED_TRACE(std::string(strain == StrainMeasure::Cauchy ? "Cauchy" : "Green") +
                   (semi ? ", semi-implicit" : ", explicit"));
      const LevelModel measured = build_level_model(mesh, damped(strain), semi, held);
      // The damped limit was measured, and it is what sets the damping scales here.
      EXPECT_TRUE(std::isfinite(level_spectra(measured).combined));
      EXPECT_LT(measured.step_damping_scale, measured.damping_spectrum.scale);
      EXPECT_EQ(level_spectra(measured).filtered != 0, semi);
      const LevelSpectra known = level_spectra(measured);
      const LevelModel given = build_level_model(mesh, damped(strain), semi, held, &known);
      expect_same_scales(measured, given);
      // K and D only where the force or the filter reads them.
      const bool needed = strain == StrainMeasure::Cauchy || semi;
      EXPECT_EQ(edge_matrices_needed(damped(strain), semi), needed);
      EXPECT_EQ(given.K.empty(), !needed);
      EXPECT_EQ(given.D.empty(), !needed);
      if (needed) {
        EXPECT_TRUE(same_bits(given.K, measured.K));
        EXPECT_TRUE(same_bits(given.D, measured.D));
      }
    }
}

// The spectra are what the scales follow: other spectra give other scales (the test above
// would pass if the known ones were ignored and measured again).
TEST(LevelModel, KnownSpectraAreTheOnesUsed) {
  const TetMesh mesh = graded_box();
  const MaterialLaw law = damped(StrainMeasure::GreenLagrange);
  const LevelModel measured = build_level_model(mesh, law, false, held_face(mesh));
  LevelSpectra other = level_spectra(measured);
  other.stiffness *= 2;
  other.combined *= 0.5;
  const LevelModel given = build_level_model(mesh, law, false, held_face(mesh), &other);
  EXPECT_EQ(given.stiffness_spectrum.eigenvalue, 2 * level_spectra(measured).stiffness);
  EXPECT_NE(given.stiffness_spectrum.scale, measured.stiffness_spectrum.scale);
  EXPECT_NE(given.step_damping_scale, measured.step_damping_scale);
}

// The Laplacian weights alone (no coefficients) are those of the whole sums, bit for bit.
TEST(EdgeOperators, WeightsAloneAreTheWeightsOfTheWholeSums) {
  const TetMesh mesh = graded_box();
  const TetGeometry geo = build_tet_geometry(mesh);
  const PointAdjacency adj = build_point_adjacency(static_cast<int>(mesh.points.size()), mesh.tets);
  const CombinedEdges whole = combined_edge_operators(geo, adj, {{4.0e4, 1.0e4}});
  const CombinedEdges alone = combined_edge_operators(geo, adj, {});
  EXPECT_TRUE(alone.matrices.empty());
  ASSERT_EQ(alone.laplacian_w.size(), adj.nbr.size());
  EXPECT_TRUE(same_bits(alone.laplacian_w, whole.laplacian_w));
  double sum = 0;
  for (double w : alone.laplacian_w) sum += std::abs(w);
  EXPECT_GT(sum, 0.0);
}
