#include "contact/contact_bound.hpp"

#include <algorithm>
#include <cmath>

#include "contact/path_box.hpp"
#include "contact/tool_shape.hpp"

namespace mrsim {

std::vector<double> penalty_stiffness(const Skin& skin, const Tool& tool, double p_wave_modulus) {
  std::vector<double> k(skin.rest.size(), tool.contact.stiffness);
  if (tool.contact.stiffness <= 0)
    for (std::size_t s = 0; s < k.size(); ++s)
      k[s] = skin.edge[s] > 0 ? p_wave_modulus / skin.edge[s] : 0.0;
  return k;
}

SkinPenalty skin_penalty(const Skin& skin, const std::vector<Tool>& tools, double p_wave_modulus) {
  SkinPenalty p;
  const std::size_t n = skin.rest.size();
  p.stiffness.assign(n, 0.0);
  p.damping.assign(n, 0.0);
  p.area = skin.area;
  for (const Tool& tool : tools) {
    const std::vector<double> k = penalty_stiffness(skin, tool, p_wave_modulus);
    for (std::size_t s = 0; s < n; ++s) {
      p.stiffness[s] = std::max(p.stiffness[s], k[s]);
      p.damping[s] = std::max(p.damping[s], tool.contact.damping);
    }
    p.area_cap = std::max(p.area_cap, contact_area(tool.shape));
  }
  return p;
}

void add_contact_bounds(const SkinPenalty& penalty, const std::vector<int>& vertices,
                        const SkinRow& row_of, std::vector<std::vector<PointInertia>>& out) {
  struct Share {
    int level, point;
    double k, c, k_peak, c_peak;  // Σ over the vertices (N/m, N·s/m); per unit area (largest)
  };
  std::vector<Share> shares;
  std::vector<ActiveTerm> row;
  for (int s : vertices) {
    row.clear();
    row_of(s, row);
    double sum = 0;
    for (const ActiveTerm& t : row) sum += std::abs(t.weight);
    for (const ActiveTerm& t : row) {
      if (t.level < 0) continue;
      const double w = std::abs(t.weight) * sum;
      shares.push_back({t.level, t.point, w * penalty.stiffness[s] * penalty.area[s],
                        w * penalty.damping[s] * penalty.area[s], w * penalty.stiffness[s],
                        w * penalty.damping[s]});
    }
  }
  std::sort(shares.begin(), shares.end(), [](const Share& a, const Share& b) {
    return a.level != b.level ? a.level < b.level : a.point < b.point;
  });
  for (std::size_t i = 0; i < shares.size();) {
    Share sum = shares[i];
    std::size_t j = i + 1;
    for (; j < shares.size() && shares[j].level == sum.level && shares[j].point == sum.point; ++j) {
      sum.k += shares[j].k;
      sum.c += shares[j].c;
      sum.k_peak = std::max(sum.k_peak, shares[j].k_peak);
      sum.c_peak = std::max(sum.c_peak, shares[j].c_peak);
    }
    PointInertia& p = out[sum.level][sum.point];
    p.contact_stiffness += std::min(sum.k, sum.k_peak * penalty.area_cap);
    p.damping += std::min(sum.c, sum.c_peak * penalty.area_cap);
    i = j;
  }
}

// Most of the skin is far from a tool's path and is passed on the path's box (path_box.hpp).
std::vector<int> reachable_skin(const Skin& skin, const std::vector<Tool>& tools, double duration,
                                double frame_dt) {
  const int samples = static_cast<int>(std::min(1e5, 16 * std::ceil(duration / frame_dt)));
  struct Path {
    std::vector<Vec3> at;
    PathBox box;
    double reach;
  };
  std::vector<Path> paths;
  for (const Tool& tool : tools) {
    std::vector<Vec3> at;
    for (int k = 0; k <= samples; ++k)
      at.push_back(tool.trajectory.pose(duration * k / samples).position);
    const PathBox box(at);
    paths.push_back({std::move(at), box, 2 * bounding_radius(tool.shape)});
  }
  auto reached = [](const Path& p, const Vec3& x) {
    if (p.box.beyond(x, p.reach)) return false;
    for (const Vec3& a : p.at)
      if ((a - x).squaredNorm() < p.reach * p.reach) return true;
    return false;
  };
  std::vector<int> out;
  for (std::size_t s = 0; s < skin.rest.size(); ++s)
    for (const Path& p : paths)
      if (reached(p, skin.rest[s])) {
        out.push_back(static_cast<int>(s));
        break;
      }
  return out;
}


}  // namespace mrsim
