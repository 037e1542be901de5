#include "hierarchy/merged_rows.hpp"

#include <cstdint>

namespace mrsim {

namespace {

// (level, point) in one integer, ordered as the pair (the support's level -1 first): the merge
// compares keys once per term and row, so one comparison instead of two.
std::uint64_t key(const ActiveTerm& t) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(t.level + 1)) << 32) |
         static_cast<std::uint32_t>(t.point);
}

}  // namespace

// The rows are each sorted with one term per point: a stable k-way merge, ties to the first row,
// sums a point's terms in the order of the rows.
void MergedRows::combine(const Span* rows, const double* weights, int count,
                         std::vector<ActiveTerm>& out) const {
  out.clear();
  int next[4];
  std::uint64_t head[4];  // the key at next[k], or past every key when row k is done
  constexpr std::uint64_t kDone = ~std::uint64_t{0};
  for (int k = 0; k < count; ++k) {
    next[k] = rows[k].begin;
    head[k] = next[k] < rows[k].end ? key(terms_[next[k]]) : kDone;
  }
  for (;;) {
    int pick = -1;  // the row holding the smallest key, the first of equal ones
    std::uint64_t least = kDone;
    for (int k = 0; k < count; ++k)
      if (head[k] < least) {
        least = head[k];
        pick = k;
      }
    if (pick < 0) return;
    const int taken = next[pick]++;
    head[pick] = next[pick] < rows[pick].end ? key(terms_[next[pick]]) : kDone;
    ActiveTerm t = terms_[taken];
    t.weight *= weights[pick];
    if (!out.empty() && out.back().level == t.level && out.back().point == t.point)
      out.back().weight += t.weight;
    else
      out.push_back(t);
  }
}

// The rule of append_active_row (method.md §4.1, §4.8): itself when active, the support when
// held, else its interpolation tet's rows weighted by its coordinates.
MergedRows::Span MergedRows::row(const Hierarchy& h,
                                 const std::vector<const std::vector<std::uint8_t>*>& free, int l,
                                 int p) {
  if (static_cast<int>(at_.size()) != h.num_levels()) at_.resize(h.num_levels());
  if (static_cast<int>(at_[l].size()) != h.num_points(l)) at_[l].assign(h.num_points(l), -1);
  if (at_[l][p] >= 0) return spans_[at_[l][p]];
  const NodeState s = h.state(l, p);
  int begin = static_cast<int>(terms_.size());
  if (s == NodeState::Active) {
    terms_.push_back({l, p, 1.0});
  } else if (!(*free[l])[p]) {  // a Dirichlet ghost or inactive point stays at rest
    terms_.push_back({-1, p, 1.0});
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
        rows[count] = this->row(h, free, source, t[k]);
        weights[count++] = e.bary[p][k];
      }
    combine(rows, weights, count, scratch_);  // reads the sources' rows in terms_
    begin = static_cast<int>(terms_.size());
    terms_.insert(terms_.end(), scratch_.begin(), scratch_.end());
  }
  const Span span{begin, static_cast<int>(terms_.size())};
  at_[l][p] = static_cast<int>(spans_.size());
  spans_.push_back(span);
  points_.emplace_back(l, p);
  return span;
}

void MergedRows::clear() {
  for (const auto& [l, p] : points_) at_[l][p] = -1;
  points_.clear();
  spans_.clear();
  terms_.clear();
}

}  // namespace mrsim
