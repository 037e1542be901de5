#pragma once
// Patch-test-consistent weights for the energy coupling (docs/hierarchy.md). With each tet
// weighted by its active share (tet_shares.hpp), a uniform stress σ exerts on an active point a
// the force -σ G_a, G_a = Σ_t w_t V_t Σ_{i∈t} J_ia ∇N_i (J the ghost interpolations, chained):
// zero inside one mesh, but not where the weights jump at an interface (up to 17 % of a
// boundary point's force). Here the weights of the interface band (tets with both active and
// ghost vertices, and the whole tets next to them) are moved, as little as possible relative to
// their shares, so that G_a = 0 at
// every free active point inside the body. Forces stay the gradient of one energy (symmetric,
// stable while the weights stay positive), and a linear displacement field - any affine state,
// Cauchy or Green strain - leaves every interior point without force: the cross-level patch test.
//
// Solved once per topology change: minimise Σ (w - w0)² / w0 subject to A w = b (3 rows per
// constrained point, one column per band tet), w = w0 + D Aᵀ λ with (A D Aᵀ) λ = b - A w0,
// D = diag(w0); weights that would leave [share / 10, 1] are held at that bound (no tet counts
// for more than once: the band is never stiffer than one mesh) and the rest solved again.
// Surface points are not constrained (their G is a boundary traction).
#include <cstdint>
#include <vector>

#include "hierarchy/hierarchy.hpp"
#include "physics/level_model.hpp"

namespace mrsim {

struct PatchTestLevel {
  const LevelModel* model = nullptr;
  const std::vector<std::uint8_t>* free_point = nullptr;  // 0: Dirichlet (force to the support)
  const std::vector<int>* live_tets = nullptr;  // tets with a non-zero share
  std::vector<double>* weight = nullptr;        // in: active shares; out: consistent weights
};

struct PatchTestReport {
  int constrained = 0;        // interior active points at interfaces
  int band_tets = 0;          // weights solved for (band tets and the whole tets around them)
  int held = 0;               // weights held at a bound
  double residual_before = 0; // max |G_a| / (Σ_t V_t |∇N_a|) over constrained points
  double residual_after = 0;
  double largest_ratio = 0;   // max over solved weights of weight / share
};

class PatchTestWeights {
 public:
  explicit PatchTestWeights(const Hierarchy& h);
  /// Adjusts the band weights of every level in place.
  PatchTestReport apply(const std::vector<PatchTestLevel>& levels);

 private:
  struct Entry {
    int row, column;
    double value;
  };
  void expand(const std::vector<PatchTestLevel>& levels, int level, int point, double coef,
              const Vec3& gradient, int column);
  int row_of(int level, int point);
  void add_column(const std::vector<PatchTestLevel>& levels, int level, int tet, double share);

  const Hierarchy& h_;
  std::vector<std::vector<std::uint8_t>> surface_;  // per level: point on the mesh's skin
  std::vector<std::vector<int>> row_;               // per level: constrained row, -1 if none
  std::vector<std::pair<int, int>> rows_;           // (level, point) of each row
  std::vector<Entry> entries_;                      // of A, 3 per (row, column) contribution
  std::vector<std::vector<int>> column_of_;         // per level and tet: column, -1 if none
  std::vector<std::pair<int, int>> columns_;        // (level, tet) of each column
  std::vector<double> share_;                       // each column's weight before
};

}  // namespace mrsim
