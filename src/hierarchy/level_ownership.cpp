#include "hierarchy/level_ownership.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "core/portable_math.hpp"
#include "hierarchy/tet_locator.hpp"
#include "mesh/tet_neighbours.hpp"

namespace mrsim {

namespace {

double tet_volume(const TetMesh& m, const Tet& t) {
  return std::abs(signed_volume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]));
}

// A uniform number in (0, 1) from a 64-bit key (splitmix64): the samples depend on the level,
// tet and sample index only, never on the run.
double uniform(std::uint64_t key) {
  key += 0x9e3779b97f4a7c15ULL;
  key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ULL;
  key = (key ^ (key >> 27)) * 0x94d049bb133111ebULL;
  key ^= key >> 31;
  return (static_cast<double>(key >> 11) + 0.5) / 9007199254740992.0;
}

// Barycentric weights of a point uniform in a tet: normalised exponentials (Dirichlet(1,1,1,1)).
std::array<double, 4> uniform_bary(std::uint64_t key) {
  std::array<double, 4> w{};
  double sum = 0;
  for (int a = 0; a < 4; ++a) sum += w[a] = -portable::log(uniform(4 * key + a));
  for (double& x : w) x /= sum;
  return w;
}

// Interleaved bits of three coordinates in [0, 1] at 10 bits each (w[1..3] of a point's
// barycentric coordinates): nearby points get nearby keys.
std::uint32_t z_order(const std::array<double, 4>& w) {
  std::uint32_t key = 0;
  for (int a = 0; a < 3; ++a) {
    const auto q = static_cast<std::uint32_t>(std::clamp(w[a + 1], 0.0, 1.0) * 1023.0);
    for (int bit = 0; bit < 10; ++bit) key |= ((q >> bit) & 1u) << (3 * bit + a);
  }
  return key;
}

double mean_tet_volume(const TetMesh& m) {
  double v = 0;
  for (const Tet& t : m.tets) v += tet_volume(m, t);
  return v / std::max<std::size_t>(1, m.tets.size());
}

std::vector<TetLocator> level_locators(const Hierarchy& h) {
  std::vector<TetLocator> locators;
  locators.reserve(h.num_levels());
  for (int m = 0; m < h.num_levels(); ++m) locators.emplace_back(*h.level(m).mesh);
  return locators;
}

}  // namespace

LevelOwnership::LevelOwnership(const Hierarchy& h) : LevelOwnership(h, level_locators(h)) {}

LevelOwnership::LevelOwnership(const Hierarchy& h, const std::vector<TetLocator>& locators)
    : levels_(h.num_levels()), start_(levels_), where_(levels_) {
  // Level 0 is never searched (owner() gives it what no finer level claims): neither its
  // neighbours nor its locator are needed.
  std::vector<std::vector<std::array<int, 4>>> neighbours(levels_);
  for (int m = 1; m < levels_; ++m) neighbours[m] = tet_neighbours(*h.level(m).mesh);
  const double unit = mean_tet_volume(*h.level(levels_ - 1).mesh);
  for (int l = 0; l < levels_; ++l) {
    const TetMesh& mesh = *h.level(l).mesh;
    start_[l].assign(mesh.tets.size() + 1, 0);
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      const double n = std::round(tet_volume(mesh, mesh.tets[t]) / unit);
      start_[l][t + 1] = start_[l][t] + static_cast<std::int32_t>(std::clamp(n, 1.0, 4096.0));
    }
    where_[l].resize(static_cast<std::size_t>(start_[l].back()) * levels_);
    // Each level's search walks from its last answer, through the samples of a tet of l in
    // Z order (of their barycentric coordinates): a coarse tet's samples, drawn at random,
    // would be a few fine tets apart; in that order they are neighbours.
    std::vector<int> last(levels_, -1);
    std::vector<Vec3> x;
    std::vector<std::pair<std::uint32_t, std::int32_t>> order;  // (Z-order key, sample)
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      const std::int32_t first = start_[l][t], count = start_[l][t + 1] - first;
      x.assign(count, Vec3::Zero());
      order.resize(count);
      for (std::int32_t i = 0; i < count; ++i) {
        const auto w = uniform_bary((static_cast<std::uint64_t>(l) << 40) + first + i);
        for (int a = 0; a < 4; ++a) x[i] += w[a] * mesh.points[mesh.tets[t][a]];
        order[i] = {z_order(w), i};
      }
      std::sort(order.begin(), order.end());
      for (const auto& [key, i] : order) {
        std::int32_t* at = &where_[l][static_cast<std::size_t>(first + i) * levels_];
        at[0] = l == 0 ? static_cast<std::int32_t>(t) : -1;
        for (int m = 1; m < levels_; ++m) {
          if (m == l) {
            at[m] = static_cast<std::int32_t>(t);
            continue;
          }
          // -1 outside level m's mesh: independent meshes of one object do not share their
          // boundary, and a level claims only what its tets cover.
          at[m] = locators[m].containing(x[i], last[m], &neighbours[m]);
          if (at[m] >= 0) last[m] = at[m];
        }
      }
    }
  }
}

bool LevelOwnership::observe(const Hierarchy& h) {
  // No status changed since the last look: neither did any tet's coverage.
  if (!covered_.empty() && observed_ == &h && observed_changes_ == h.status_changes())
    return false;
  observed_ = &h;
  observed_changes_ = h.status_changes();
  bool changed = covered_.empty();
  covered_.resize(levels_);
  for (int m = 0; m < levels_; ++m) {
    const TetMesh& mesh = *h.level(m).mesh;
    covered_[m].resize(mesh.tets.size());
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      bool covered = true;
      for (int v : mesh.tets[t]) covered = covered && h.state(m, v) != NodeState::Inactive;
      changed = changed || covered_[m][t] != covered;
      covered_[m][t] = covered;
    }
  }
  return changed;
}

// A finer level claims x only inside its own mesh, where its tet has no inactive vertex;
// level 0 takes the rest.
int LevelOwnership::owner(const std::int32_t* at) const {
  for (int m = levels_ - 1; m > 0; --m)
    if (at[m] >= 0 && covered_[m][at[m]]) return m;
  return 0;
}

void LevelOwnership::shares(int level, std::vector<double>& share,
                            std::vector<std::int8_t>& owner_level) const {
  const std::size_t tets = start_[level].size() - 1;
  share.resize(tets);
  owner_level.resize(tets);
  std::vector<int> count(levels_);
  for (std::size_t t = 0; t < tets; ++t) {
    std::fill(count.begin(), count.end(), 0);
    for (std::int32_t s = start_[level][t]; s < start_[level][t + 1]; ++s)
      ++count[owner(&where_[level][static_cast<std::size_t>(s) * levels_])];
    share[t] = static_cast<double>(count[level]) / (start_[level][t + 1] - start_[level][t]);
    // max_element: the first of equal counts, the coarser level.
    owner_level[t] =
        static_cast<std::int8_t>(std::max_element(count.begin(), count.end()) - count.begin());
  }
}

}  // namespace mrsim
