#include "hierarchy/tet_locator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "hierarchy/closest_point.hpp"

namespace mrsim {

namespace {
constexpr double kInsideTolerance = 1e-12;  // barycentric slack for points on faces
constexpr int kMaxCells = 1 << 24;
}  // namespace

TetLocator::TetLocator(const TetMesh& mesh) : mesh_(mesh) {
  const size_t nt = mesh.tets.size();
  inverse_.resize(nt);
  Vec3 lo = mesh.points.front(), hi = lo;
  for (const Vec3& p : mesh.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // The grid is built on the exact boxes, the tests use the grown ones (Box).
  std::vector<Box> exact(nt);
  box_.resize(nt);
  for (size_t t = 0; t < nt; ++t) {
    const Tet& v = mesh.tets[t];
    Mat3 D;
    for (int k = 0; k < 3; ++k) D.col(k) = mesh.points[v[k + 1]] - mesh.points[v[0]];
    inverse_[t] = D.inverse();
    Box& b = exact[t];
    b.lo = b.hi = mesh.points[v[0]];
    for (int a = 1; a < 4; ++a) {
      b.lo = b.lo.cwiseMin(mesh.points[v[a]]);
      b.hi = b.hi.cwiseMax(mesh.points[v[a]]);
    }
    const Vec3 slack = Vec3::Constant(1e-6 * (b.hi - b.lo).maxCoeff());
    box_[t] = {b.lo - slack, b.hi + slack};
  }
  // About one tet per cell: h³ ≈ bbox volume / T, capped so the grid stays bounded.
  const Vec3 ext = (hi - lo).cwiseMax(1e-12);
  h_ = std::cbrt(ext.prod() / std::max<size_t>(nt, 1));
  h_ = std::max(h_, ext.maxCoeff() / 1024.0);
  while (static_cast<double>(std::ceil(ext.x() / h_) * std::ceil(ext.y() / h_) *
                             std::ceil(ext.z() / h_)) > kMaxCells)
    h_ *= 1.25;
  lo_ = lo;
  for (int k = 0; k < 3; ++k) dims_[k] = std::max(1, static_cast<int>(std::ceil(ext[k] / h_)));
  // Two passes (count, fill) into CSR: tets in every cell their bounding box overlaps.
  const int ncells = dims_[0] * dims_[1] * dims_[2];
  cell_start_.assign(ncells + 1, 0);
  auto for_cells = [&](size_t t, auto&& fn) {
    const auto ca = cell_of(exact[t].lo), cb = cell_of(exact[t].hi);
    for (int k = ca[2]; k <= cb[2]; ++k)
      for (int j = ca[1]; j <= cb[1]; ++j)
        for (int i = ca[0]; i <= cb[0]; ++i) fn(cell_index(i, j, k));
  };
  for (size_t t = 0; t < nt; ++t) for_cells(t, [&](int c) { ++cell_start_[c + 1]; });
  for (int c = 0; c < ncells; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_tets_.resize(cell_start_[ncells]);
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (size_t t = 0; t < nt; ++t)
    for_cells(t, [&](int c) { cell_tets_[fill[c]++] = static_cast<int>(t); });
}

std::array<int, 3> TetLocator::cell_of(const Vec3& p) const {
  std::array<int, 3> c;
  for (int k = 0; k < 3; ++k) {
    // floor() then a clamp to [0, dims − 1]: truncation is the floor for x ≥ 0, and x < 0 (or
    // NaN) is cell 0 either way. Clamped as a double, far points convert without overflow.
    const double x = (p[k] - lo_[k]) / h_;
    c[k] = x >= 0 ? static_cast<int>(std::min(x, dims_[k] - 1.0)) : 0;
  }
  return c;
}

std::array<double, 4> TetLocator::barycentric(int t, const Vec3& p) const {
  const Vec3 b = inverse_[t] * (p - mesh_.points[mesh_.tets[t][0]]);
  return {1.0 - b.sum(), b.x(), b.y(), b.z()};
}

double TetLocator::distance_to_tet(int t, const Vec3& p, const std::array<double, 4>& b) const {
  if (*std::min_element(b.begin(), b.end()) >= -kInsideTolerance) return 0;
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  const Tet& v = mesh_.tets[t];
  double d = std::numeric_limits<double>::infinity();
  for (const auto& f : kFaces) {
    const Vec3 q = closest_point_on_triangle(p, mesh_.points[v[f[0]]], mesh_.points[v[f[1]]],
                                             mesh_.points[v[f[2]]]);
    d = std::min(d, (p - q).norm());
  }
  return d;
}

// Best = smallest distance; among containing tets (distance 0), the largest minimum
// barycentric coordinate; ties broken by the lowest tet index (candidates come in any order).
double TetLocator::box_gap(int t, const Vec3& p) const {
  return (box_[t].lo - p).cwiseMax(p - box_[t].hi).cwiseMax(0.0).norm();
}

double TetLocator::plane_gap(int t, const std::array<double, 4>& b) const {
  // λ_k's gradient is row k of D⁻¹ (k = 1..3), and minus their sum for k = 0: the distance to
  // face k's plane is −λ_k / |∇λ_k|.
  const Mat3& inv = inverse_[t];
  double gap = 0;
  for (int k = 0; k < 4; ++k)
    if (b[k] < 0) {
      const Vec3 grad = k == 0 ? Vec3(-inv.colwise().sum().transpose()) : Vec3(inv.row(k - 1));
      gap = std::max(gap, -b[k] / grad.norm());
    }
  return gap;
}

void TetLocator::consider(int t, double gap, const Vec3& p, TetLocation& best,
                          double& best_key) const {
  // A tet whose bounding box, or a face's plane, is farther than the best so far cannot win
  // nor tie (the margins cover rounding): skipped without its four closest-point queries. The
  // result is the same.
  const double bound = std::max(best_key, 0.0) * (1 + 1e-9) + 1e-300;
  if (best.tet >= 0 && gap > bound) return;
  const auto b = barycentric(t, p);
  if (best.tet >= 0 && plane_gap(t, b) * (1 - 1e-6) > bound) return;
  const double d = distance_to_tet(t, p, b);
  const double key = d > 0 ? d : -*std::min_element(b.begin(), b.end());
  if (best.tet < 0 || key < best_key || (key == best_key && t < best.tet)) {
    best.tet = t;
    best.bary = b;
    best.distance = d;
    best_key = key;
  }
}

// Every tet containing p overlaps p's cell (its bounding box holds p), so that cell decides,
// and no distance is needed: the containing tet with the largest smallest coordinate, ties to
// the lowest index.
int TetLocator::containing(const Vec3& p) const {
  const auto c = cell_of(p);
  const int cell = cell_index(c[0], c[1], c[2]);
  int best = -1;
  double best_min = 0;
  for (int s = cell_start_[cell]; s < cell_start_[cell + 1]; ++s) {
    const int t = cell_tets_[s];
    // Six comparisons instead of a barycentric solve for the cell's other tets.
    const Box& box = box_[t];
    if (p.x() < box.lo.x() || p.y() < box.lo.y() || p.z() < box.lo.z() || p.x() > box.hi.x() ||
        p.y() > box.hi.y() || p.z() > box.hi.z())
      continue;
    const auto b = barycentric(t, p);
    const double m = *std::min_element(b.begin(), b.end());
    if (m < -kInsideTolerance) continue;
    if (best < 0 || m > best_min || (m == best_min && t < best)) {
      best = t;
      best_min = m;
    }
  }
  return best;
}

int TetLocator::containing(const Vec3& p, int hint,
                           const std::vector<std::array<int, 4>>* neighbours) const {
  // Another tet wins only with a larger smallest coordinate, i.e. holding p by more than this
  // margin too: the two would overlap. 1e-4 leaves room for the coordinates' rounding.
  constexpr double kClearlyInside = 1e-4;
  // A walk that meets a face shared by no tet, or circles, ends in the cell's search.
  for (int step = 0; step < 64 && hint >= 0 && hint < static_cast<int>(inverse_.size()); ++step) {
    const auto b = barycentric(hint, p);
    const auto beyond = std::min_element(b.begin(), b.end());
    if (*beyond >= kClearlyInside) return hint;
    if (!neighbours) break;
    if (step == 0 && *beyond < -1) {
      // Farther beyond the hint than its own size: the walk starts again from a tet listed in
      // p's grid cell, which is nearer.
      const auto c = cell_of(p);
      const int cell = cell_index(c[0], c[1], c[2]);
      hint = cell_start_[cell] < cell_start_[cell + 1] ? cell_tets_[cell_start_[cell]] : -1;
      continue;
    }
    hint = (*neighbours)[hint][beyond - b.begin()];
  }
  return containing(p);
}

// Tets overlap several cells: a query meets the same tet in each. The tets it has considered
// are stamped (per thread: locate() runs in parallel loops) so that each is measured once.
namespace {
struct Stamps {
  std::vector<std::uint32_t> of_tet;
  std::vector<std::pair<double, int>> candidates;  // one cell's new tets, by box gap
  std::uint32_t query = 0;
  void next(std::size_t tets) {
    if (of_tet.size() < tets) of_tet.resize(tets, 0);
    if (++query == 0) {  // wrapped: every old stamp could collide
      std::fill(of_tet.begin(), of_tet.end(), 0);
      query = 1;
    }
  }
  bool first_time(int t) {
    if (of_tet[t] == query) return false;
    of_tet[t] = query;
    return true;
  }
};
thread_local Stamps stamps;
}  // namespace

TetLocation TetLocator::locate(const Vec3& p) const {
  // Inside: the containing tet, without the distances of the cell's other tets.
  if (const int t = containing(p); t >= 0) return {t, barycentric(t, p), 0.0};
  TetLocation best;
  double best_key = 0;
  stamps.next(mesh_.tets.size());
  const auto c = cell_of(p);
  // A cell's new tets nearest box first: the best comes early and prunes the rest.
  std::vector<std::pair<double, int>>& near = stamps.candidates;
  auto visit = [&](int cell) {
    near.clear();
    for (int s = cell_start_[cell]; s < cell_start_[cell + 1]; ++s)
      if (stamps.first_time(cell_tets_[s]))
        near.emplace_back(box_gap(cell_tets_[s], p), cell_tets_[s]);
    std::sort(near.begin(), near.end());
    for (const auto& [gap, t] : near) consider(t, gap, p, best, best_key);
  };
  visit(cell_index(c[0], c[1], c[2]));
  if (best.tet >= 0 && best.distance == 0) return best;
  // Outside every tet of the cell: search rings of cells until no closer tet can exist. A cell
  // farther than the best so far is skipped: a tet all of whose cells are skipped has its
  // bounding box, hence itself, farther too (consider() would skip it), so the result is the
  // same.
  const int max_ring = std::max({dims_[0], dims_[1], dims_[2]});
  for (int r = 1; r <= max_ring; ++r) {
    for (int k = std::max(c[2] - r, 0); k <= std::min(c[2] + r, dims_[2] - 1); ++k)
      for (int j = std::max(c[1] - r, 0); j <= std::min(c[1] + r, dims_[1] - 1); ++j) {
        // The ring's shell only: inside its two faces in k and j, just the two ends in i.
        const bool face = std::abs(k - c[2]) == r || std::abs(j - c[1]) == r;
        const int step = face ? 1 : 2 * r;
        for (int i = c[0] - r; i <= c[0] + r; i += step) {
          if (i < 0 || i >= dims_[0]) continue;
          if (best.tet >= 0) {
            const Vec3 cell_lo = lo_ + h_ * Vec3(i, j, k), cell_hi = cell_lo + Vec3::Constant(h_);
            const Vec3 gap = (cell_lo - p).cwiseMax(p - cell_hi).cwiseMax(0.0);
            if (gap.norm() > std::max(best_key, 0.0) * (1 + 1e-9) + 1e-300) continue;
          }
          visit(cell_index(i, j, k));
        }
      }
    // Every tet not yet seen lies in cells at least r·h away from p's cell.
    if (best.tet >= 0 && best.distance <= r * h_) break;
  }
  return best;
}

}  // namespace mrsim
