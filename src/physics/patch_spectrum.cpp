#include "physics/patch_spectrum.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/spectral_bound.hpp"

namespace mrsim {

namespace {

// A point that moves: a finite positive mass (a held point's is infinite).
bool free_mass(double m) { return std::isfinite(m) && m > 0; }

// The filtered operator on the patch `points` (mass-scaled), dense: (A u)_a = Σ_j A_aj (u_j +
// u_a) over every neighbour j of a, those outside the patch held at zero. `slot`: -1 for every
// point on entry and on return; the patch's local index meanwhile.
double patch_eigenvalue(const PointAdjacency& adj, const std::vector<Mat3>& edge,
                        const std::vector<double>& mass, const std::vector<int>& points,
                        std::vector<int>& slot, Eigen::MatrixXd& a) {
  const int k = static_cast<int>(points.size());
  for (int r = 0; r < k; ++r) slot[points[r]] = r;
  a.setZero(3 * k, 3 * k);
  for (int r = 0; r < k; ++r) {
    const int p = points[r];
    Mat3 own = Mat3::Zero();
    for (int e = adj.nbr_start[p]; e < adj.nbr_start[p + 1]; ++e) {
      own += edge[e];
      const int c = slot[adj.nbr[e]];
      if (c >= 0) a.block<3, 3>(3 * r, 3 * c) = edge[e] / std::sqrt(mass[p] * mass[adj.nbr[e]]);
    }
    a.block<3, 3>(3 * r, 3 * r) = own / mass[p];
  }
  for (const int q : points) slot[q] = -1;
  const Eigen::MatrixXd sym = 0.5 * (a + a.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(sym, Eigen::EigenvaluesOnly);
  return es.eigenvalues()[3 * k - 1];
}

}  // namespace

std::vector<double> patch_filtered_eigenvalues(const PointAdjacency& adj,
                                               const std::vector<Mat3>& edge,
                                               const std::vector<double>& mass) {
  const int n = adj.num_points();
  std::vector<double> out(n, -std::numeric_limits<double>::infinity());
  std::vector<int> points, slot(n, -1);
  Eigen::MatrixXd a;
  for (int i = 0; i < n; ++i) {
    if (!free_mass(mass[i])) continue;
    points.assign(1, i);
    for (int e = adj.nbr_start[i]; e < adj.nbr_start[i + 1]; ++e)
      if (free_mass(mass[adj.nbr[e]])) points.push_back(adj.nbr[e]);
    out[i] = patch_eigenvalue(adj, edge, mass, points, slot, a);
  }
  return out;
}

std::vector<double> time_level_filter_shares(const PointAdjacency& adj,
                                             const std::vector<double>& patch_eigenvalue,
                                             const std::vector<PointInertia>& star) {
  const int n = adj.num_points();
  std::vector<double> share(n, kSemiImplicitShare);
  for (int i = 0; i < n; ++i) {
    if (!(star[i].stiffness > 0) || !(star[i].mass > 0)) continue;
    double l = patch_eigenvalue[i];
    for (int e = adj.nbr_start[i]; e < adj.nbr_start[i + 1]; ++e)
      l = std::max(l, patch_eigenvalue[adj.nbr[e]]);
    const double s = kSpectralMargin * l * star[i].mass / star[i].stiffness;
    share[i] = std::clamp(s, kFilterStiffening, kSemiImplicitShare);
  }
  return share;
}

void raise_to_level_share(std::vector<double>& share, double filtered, double star_max) {
  if (!(star_max > 0) || !(filtered > 0)) return;
  const double level = std::min(kSemiImplicitShare, kSpectralMargin * filtered / star_max);
  for (double& s : share) s = std::max(s, level);
}

}  // namespace mrsim
