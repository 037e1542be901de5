#include "contact/skin_map.hpp"

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

}  // namespace

void SkinMap::build(const Hierarchy& h, const SkinBinding& b,
                    const std::vector<const std::vector<std::uint8_t>*>& free_point) {
  const int n = static_cast<int>(b.tet[0].size());
  rows_.clear();  // the statuses changed since the last build
  level_.resize(n);
  start_.assign(1, 0);
  terms_.clear();
  for (int s = 0; s < n; ++s) {
    const int l = moving_level(h, b, s);
    level_[s] = l;
    const Tet& t = h.level(l).mesh->tets[b.tet[l][s]];
    MergedRows::Span rows[4];
    double weights[4];
    int count = 0;
    for (int k = 0; k < 4; ++k)
      if (b.bary[l][s][k] != 0) {
        rows[count] = rows_.row(h, free_point, l, t[k]);
        weights[count++] = b.bary[l][s][k];
      }
    rows_.combine(rows, weights, count, row_);
    terms_.insert(terms_.end(), row_.begin(), row_.end());
    start_.push_back(static_cast<int>(terms_.size()));
  }
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
