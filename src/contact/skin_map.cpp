#include "contact/skin_map.hpp"

namespace mrsim {

namespace {

// Does level l move skin vertex s: is every vertex of its tet there with a weight not inactive?
bool moves(const Hierarchy& h, const SkinBinding& b, int l, int s) {
  const Tet& t = h.level(l).mesh->tets[b.tet[l][s]];
  for (int k = 0; k < 4; ++k)
    if (b.bary[l][s][k] != 0 && h.state(l, t[k]) == NodeState::Inactive) return false;
  return true;
}

}  // namespace

// Each vertex takes the finest level that moves it (level 0 when none does). Level by level,
// finest first, over the vertices still undecided: each pass reads its level's binding in
// order, where vertex by vertex every level's was read at random (at each topology change:
// 1.4 % of liver_probe's time). The same levels.
void SkinMap::build(const Hierarchy& h, const SkinBinding& b,
                    const std::vector<const std::vector<std::uint8_t>*>& free_point) {
  const int n = static_cast<int>(b.tet[0].size());
  h_ = &h;
  free_ = free_point;
  level_.assign(n, 0);
  source_.resize(n);
  weight_.resize(n);
  undecided_.resize(n);
  for (int s = 0; s < n; ++s) undecided_[s] = s;
  for (int l = h.num_levels() - 1; l > 0; --l) {
    std::size_t kept = 0;
    for (const int s : undecided_)
      if (moves(h, b, l, s))
        level_[s] = l;
      else
        undecided_[kept++] = s;
    undecided_.resize(kept);
  }
  for (int s = 0; s < n; ++s) {
    source_[s] = h.level(level_[s]).mesh->tets[b.tet[level_[s]][s]];
    weight_[s] = b.bary[level_[s]][s];
  }
  // Forget the rows of the last build (the statuses changed since).
  if (static_cast<int>(begin_.size()) != n) {
    begin_.assign(n, -1);
    end_.assign(n, -1);
  } else {
    for (int s : built_) begin_[s] = -1;
  }
  built_.clear();
  terms_.clear();
  rows_.clear();
}

void SkinMap::interpolate(int s, const std::vector<LevelFields>& fields, Vec3& u, Vec3& v) const {
  const LevelFields& f = fields[level_[s]];
  u = Vec3::Zero();
  v = Vec3::Zero();
  for (int k = 0; k < 4; ++k)
    if (weight_[s][k] != 0) {  // a vertex of weight 0 may be inactive: not read
      u += weight_[s][k] * f.u[source_[s][k]];
      v += weight_[s][k] * f.v[source_[s][k]];
    }
}

std::span<const ActiveTerm> SkinMap::row(int s) const {
  if (begin_[s] < 0) {
    const int l = level_[s];
    MergedRows::Span rows[4];
    double weights[4];
    int count = 0;
    for (int k = 0; k < 4; ++k)
      if (weight_[s][k] != 0) {
        rows[count] = rows_.row(*h_, free_, l, source_[s][k]);
        weights[count++] = weight_[s][k];
      }
    rows_.combine(rows, weights, count, scratch_);
    begin_[s] = static_cast<int>(terms_.size());
    terms_.insert(terms_.end(), scratch_.begin(), scratch_.end());
    end_[s] = static_cast<int>(terms_.size());
    built_.push_back(s);
  }
  return {terms_.data() + begin_[s], terms_.data() + end_[s]};
}

Vec3 SkinMap::value(int s, const std::vector<LevelFields>& fields, bool velocity) const {
  Vec3 x = Vec3::Zero();
  for (const ActiveTerm& t : row(s))
    if (t.level >= 0) {
      const LevelFields& f = fields[t.level];
      x += t.weight * (velocity ? f.v[t.point] : f.u[t.point]);
    }
  return x;
}

}  // namespace mrsim
