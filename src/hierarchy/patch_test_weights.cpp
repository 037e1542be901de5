#include "hierarchy/patch_test_weights.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

#include "mesh/boundary_faces.hpp"

namespace mrsim {

namespace {

constexpr double kFloor = 0.1;   // a weight never falls below this fraction of its share
constexpr double kCeiling = 1.0; // nor rises above a whole tet: the band never gets stiffer than
                                 // one mesh, so the stable step stays that of the levels
constexpr int kHoldRounds = 50;  // each round holds the weights that went below their floor

using SparseMatrix = Eigen::SparseMatrix<double>;

// w = base + D Aᵀ λ with (A D Aᵀ) λ = b - A base: the weights nearest to `base` (in the metric
// of D) that satisfy A w = b, or the least-squares compromise when the rows are dependent.
Eigen::VectorXd nearest_consistent(const SparseMatrix& A, const Eigen::VectorXd& b,
                                   const Eigen::VectorXd& base, const Eigen::VectorXd& d) {
  const SparseMatrix AD = A * d.asDiagonal();
  SparseMatrix M = AD * A.transpose();
  double largest = 0;
  for (int k = 0; k < M.rows(); ++k) largest = std::max(largest, M.coeff(k, k));
  for (int k = 0; k < M.rows(); ++k) M.coeffRef(k, k) += 1e-12 * largest + 1e-300;
  Eigen::SimplicialLDLT<SparseMatrix> solver(M);
  if (solver.info() != Eigen::Success) return base;
  const Eigen::VectorXd lambda = solver.solve(b - A * base);
  return base + AD.transpose() * lambda;
}

}  // namespace

PatchTestWeights::PatchTestWeights(const Hierarchy& h) : h_(h) {
  for (int l = 0; l < h.num_levels(); ++l) {
    const TetMesh& mesh = *h.level(l).mesh;
    surface_.emplace_back(mesh.points.size(), std::uint8_t{0});
    for (const Face& f : boundary_faces(mesh))
      for (int p : f) surface_[l][p] = 1;
    row_.emplace_back(mesh.points.size(), -1);
    column_of_.emplace_back();
  }
}

int PatchTestWeights::row_of(int level, int point) {
  if (surface_[level][point]) return -1;
  int& r = row_[level][point];
  if (r < 0) {
    r = static_cast<int>(rows_.size());
    rows_.emplace_back(level, point);
  }
  return r;
}

// The contribution coef × V ∇N of a band tet's vertex reaches the active points that move it:
// itself, or through its interpolation tet (chained, as the ghost force transfer does).
void PatchTestWeights::expand(const std::vector<PatchTestLevel>& levels, int level, int point,
                              double coef, const Vec3& gradient, int column) {
  if (!(*levels[level].free_point)[point]) return;  // held by the support
  const NodeState s = h_.state(level, point);
  if (s == NodeState::Active) {
    const int r = row_of(level, point);
    if (r >= 0)
      for (int d = 0; d < 3; ++d) entries_.push_back({3 * r + d, column, coef * gradient[d]});
    return;
  }
  if (s != NodeState::GhostSub && s != NodeState::GhostIface) return;
  const bool finer = s == NodeState::GhostSub;
  const Embedding& e = finer ? h_.links(level).child_tet : h_.links(level).parent_tet;
  const int source = finer ? level + 1 : level - 1;
  const Tet& t = h_.level(source).mesh->tets[e.tet[point]];
  for (int k = 0; k < 4; ++k)
    if (e.bary[point][k] != 0)
      expand(levels, source, t[k], coef * e.bary[point][k], gradient, column);
}

// The band tets, then the whole tets around the points the band reaches (more freedom: the
// band alone cannot always be balanced with positive weights); every interior point such a
// column reaches becomes a constraint, so moving a whole tet cannot spoil a point it touches.
void PatchTestWeights::add_column(const std::vector<PatchTestLevel>& levels, int l, int t,
                                  double share) {
  const LevelModel& m = *levels[l].model;
  column_of_[l][t] = static_cast<int>(columns_.size());
  columns_.emplace_back(l, t);
  share_.push_back(share);
  for (int k = 0; k < 4; ++k)
    expand(levels, l, m.mesh->tets[t][k], 1.0, m.geo.volume[t] * m.geo.grad[t][k],
           column_of_[l][t]);
}

PatchTestReport PatchTestWeights::apply(const std::vector<PatchTestLevel>& levels) {
  PatchTestReport report;
  rows_.clear();
  entries_.clear();
  columns_.clear();
  share_.clear();
  for (int l = 0; l < static_cast<int>(levels.size()); ++l) {
    if (!levels[l].weight) continue;
    if (column_of_[l].size() != levels[l].weight->size()) column_of_[l].assign(levels[l].weight->size(), -1);
    for (int t : *levels[l].live_tets) {
      const double w = (*levels[l].weight)[t];
      if (w > 0 && w < 1) add_column(levels, l, t, w);
    }
  }
  const int band_rows = static_cast<int>(rows_.size());
  for (int r = 0; r < band_rows; ++r) {
    const auto [l, a] = rows_[r];
    if (!levels[l].weight) continue;
    const LevelModel& m = *levels[l].model;
    for (int s = m.adj.inc_start[a]; s < m.adj.inc_start[a + 1]; ++s) {
      const int t = m.adj.inc_tet[s];
      if ((*levels[l].weight)[t] == 1.0 && column_of_[l][t] < 0) add_column(levels, l, t, 1.0);
    }
  }
  const int n = static_cast<int>(columns_.size()), rows = static_cast<int>(rows_.size());
  report.constrained = rows;
  report.band_tets = n;
  if (rows == 0 || n == 0) {
    for (auto [l, p] : rows_) row_[l][p] = -1;
    for (auto [l, t] : columns_) column_of_[l][t] = -1;
    return report;
  }
  // b: minus what the whole tets around each constrained point give it; scale: Σ V |∇N|.
  Eigen::VectorXd b = Eigen::VectorXd::Zero(3 * rows), scale = Eigen::VectorXd::Zero(rows);
  for (int r = 0; r < rows; ++r) {
    const auto [l, a] = rows_[r];
    const LevelModel& m = *levels[l].model;
    for (int s = m.adj.inc_start[a]; s < m.adj.inc_start[a + 1]; ++s) {
      const int t = m.adj.inc_tet[s];
      const Vec3 g = m.geo.volume[t] * m.geo.grad[t][m.adj.inc_local[s]];
      scale[r] += g.norm();
      const bool whole = !levels[l].weight || (*levels[l].weight)[t] == 1.0;
      if (whole && (!levels[l].weight || column_of_[l][t] < 0)) b.segment<3>(3 * r) -= g;
    }
  }
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(entries_.size());
  for (const Entry& e : entries_) triplets.emplace_back(e.row, e.column, e.value);
  SparseMatrix A(3 * rows, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  auto worst = [&](const Eigen::VectorXd& w) {
    const Eigen::VectorXd r = A * w - b;
    double x = 0;
    for (int k = 0; k < rows; ++k) x = std::max(x, r.segment<3>(3 * k).norm() / scale[k]);
    return x;
  };
  const Eigen::VectorXd w0 = Eigen::Map<const Eigen::VectorXd>(share_.data(), n);
  report.residual_before = worst(w0);
  Eigen::VectorXd base = w0, d = w0, w = w0;
  const Eigen::VectorXd lo = kFloor * w0, hi = Eigen::VectorXd::Constant(n, kCeiling);
  for (int round = 0; round < kHoldRounds; ++round) {
    w = nearest_consistent(A, b, base, d);
    bool held = false;
    for (int c = 0; c < n; ++c)
      if (d[c] > 0 && (w[c] < lo[c] || w[c] > hi[c])) {  // hold it at its bound, solve the rest
        base[c] = w[c] < lo[c] ? lo[c] : hi[c];
        d[c] = 0;
        held = true;
      }
    if (!held) break;
    if (round + 1 == kHoldRounds) w = w.cwiseMax(lo).cwiseMin(hi);
  }
  for (int c = 0; c < n; ++c) {
    report.held += d[c] == 0;
    report.largest_ratio = std::max(report.largest_ratio, w[c] / w0[c]);
  }
  report.residual_after = worst(w);
  for (int c = 0; c < n; ++c) (*levels[columns_[c].first].weight)[columns_[c].second] = w[c];
  for (auto [l, p] : rows_) row_[l][p] = -1;
  for (auto [l, t] : columns_) column_of_[l][t] = -1;
  return report;
}

}  // namespace mrsim
