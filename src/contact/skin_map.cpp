#include "contact/skin_map.hpp"

#include <algorithm>
#include <tuple>

namespace mrsim {

namespace {

int moving_level(const Hierarchy& h, const SkinBinding& b, int s) {
  for (int l = h.num_levels() - 1; l > 0; --l) {
    const Tet& t = h.level(l).mesh->tets[b.tet[l][s]];
    bool all = true;
    for (int k = 0; k < 4; ++k)
      if (b.bary[l][s][k] != 0 && h.state(l, t[k]) == NodeState::Inactive) all = false;
    if (all) return l;
  }
  return 0;
}

bool key_less(const ActiveTerm& a, const ActiveTerm& b) {
  return std::tuple(a.level, a.point) < std::tuple(b.level, b.point);
}

}  // namespace

// Σ weights[k] × rows[k]: the rows (each sorted by (level, point), one term per point) merged in
// that order, the same point's terms summed in the order of the rows, so a row is short and the
// forces it carries are summed in a fixed order.
void SkinMap::combine(const Span* rows, const double* weights, int count,
                      std::vector<ActiveTerm>& out) {
  out.clear();
  int next[4];
  for (int k = 0; k < count; ++k) next[k] = rows[k].begin;
  for (;;) {
    int pick = -1;  // the row holding the smallest key; ties to the first row
    for (int k = 0; k < count; ++k)
      if (next[k] < rows[k].end &&
          (pick < 0 || key_less(memo_terms_[next[k]], memo_terms_[next[pick]])))
        pick = k;
    if (pick < 0) return;
    ActiveTerm t = memo_terms_[next[pick]++];
    t.weight *= weights[pick];
    if (!out.empty() && out.back().level == t.level && out.back().point == t.point)
      out.back().weight += t.weight;
    else
      out.push_back(t);
  }
}

// The row of a point (method.md §4.1, §4.8; hierarchy/active_row.hpp): itself when active, the
// support when held, else its interpolation tet's rows weighted by its coordinates. Each point's
// row is built once per build (ghost chains share their sources).
SkinMap::Span SkinMap::point_row(const Hierarchy& h,
                                 const std::vector<const std::vector<std::uint8_t>*>& free,
                                 int l, int p) {
  if (memo_at_[l][p] >= 0) return memo_span_[memo_at_[l][p]];
  std::vector<ActiveTerm> row;
  const NodeState s = h.state(l, p);
  if (s == NodeState::Active) {
    row.push_back({l, p, 1.0});
  } else if (!(*free[l])[p]) {  // a Dirichlet ghost or inactive point stays at rest
    row.push_back({-1, p, 1.0});
  } else {
    const bool finer = s == NodeState::GhostSub;
    const Embedding& e = finer ? h.links(l).child_tet : h.links(l).parent_tet;
    const int source = finer ? l + 1 : l - 1;
    const Tet& t = h.level(source).mesh->tets[e.tet[p]];
    Span rows[4];
    double weights[4];
    int count = 0;
    for (int k = 0; k < 4; ++k)
      if (e.bary[p][k] != 0) {
        rows[count] = point_row(h, free, source, t[k]);
        weights[count++] = e.bary[p][k];
      }
    combine(rows, weights, count, row);
  }
  const Span span{static_cast<int>(memo_terms_.size()),
                  static_cast<int>(memo_terms_.size() + row.size())};
  memo_terms_.insert(memo_terms_.end(), row.begin(), row.end());
  memo_at_[l][p] = static_cast<int>(memo_span_.size());
  memo_span_.push_back(span);
  memo_points_.emplace_back(l, p);
  return span;
}

void SkinMap::build(const Hierarchy& h, const SkinBinding& b,
                    const std::vector<const std::vector<std::uint8_t>*>& free_point) {
  const int n = static_cast<int>(b.tet[0].size());
  memo_at_.resize(h.num_levels());
  for (int l = 0; l < h.num_levels(); ++l) memo_at_[l].resize(h.num_points(l), -1);
  level_.resize(n);
  start_.assign(1, 0);
  terms_.clear();
  for (int s = 0; s < n; ++s) {
    const int l = moving_level(h, b, s);
    level_[s] = l;
    const Tet& t = h.level(l).mesh->tets[b.tet[l][s]];
    Span rows[4];
    double weights[4];
    int count = 0;
    for (int k = 0; k < 4; ++k)
      if (b.bary[l][s][k] != 0) {
        rows[count] = point_row(h, free_point, l, t[k]);
        weights[count++] = b.bary[l][s][k];
      }
    combine(rows, weights, count, row_);
    terms_.insert(terms_.end(), row_.begin(), row_.end());
    start_.push_back(static_cast<int>(terms_.size()));
  }
  for (const auto& [l, p] : memo_points_) memo_at_[l][p] = -1;
  memo_points_.clear();
  memo_span_.clear();
  memo_terms_.clear();
}

Vec3 SkinMap::value(int s, const std::vector<LevelFields>& fields, bool velocity) const {
  Vec3 x = Vec3::Zero();
  for (const ActiveTerm* t = begin(s); t != end(s); ++t)
    if (t->level >= 0) {
      const LevelFields& f = fields[t->level];
      x += t->weight * (velocity ? f.v[t->point] : f.u[t->point]);
    }
  return x;
}

void SkinMap::values(int s, const std::vector<LevelFields>& fields, Vec3& u, Vec3& v) const {
  u = Vec3::Zero();
  v = Vec3::Zero();
  for (const ActiveTerm* t = begin(s); t != end(s); ++t)
    if (t->level >= 0) {
      const LevelFields& f = fields[t->level];
      u += t->weight * f.u[t->point];
      v += t->weight * f.v[t->point];
    }
}

}  // namespace mrsim
