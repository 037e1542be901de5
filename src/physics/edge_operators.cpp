#include "physics/edge_operators.hpp"

namespace mrsim {

namespace {

// The CSR entry of each neighbour j of one point i, looked up by j in O(1) instead of a binary
// search of i's list: set for i, reset after (O(degree) each).
class NeighbourSlots {
 public:
  explicit NeighbourSlots(int points) : slot_(points, -1) {}
  void set(const PointAdjacency& adj, int i) {
    for (int e = adj.nbr_start[i]; e < adj.nbr_start[i + 1]; ++e) slot_[adj.nbr[e]] = e;
  }
  void reset(const PointAdjacency& adj, int i) {
    for (int e = adj.nbr_start[i]; e < adj.nbr_start[i + 1]; ++e) slot_[adj.nbr[e]] = -1;
  }
  int operator[](int j) const { return slot_[j]; }

 private:
  std::vector<int> slot_;
};

}  // namespace

EdgeOperators build_edge_operators(const TetGeometry& geo, const PointAdjacency& adj) {
  EdgeOperators ops;
  ops.A.assign(adj.nbr.size(), Mat3::Zero());
  ops.B.assign(adj.nbr.size(), Mat3::Zero());
  const int n = adj.num_points();
  NeighbourSlots slot(n);
  // Per point i, gather from its incident tets: entry (i, j) for every other vertex j.
  for (int i = 0; i < n; ++i) {
    slot.set(adj, i);
    for (int s = adj.inc_start[i]; s < adj.inc_start[i + 1]; ++s) {
      const int t = adj.inc_tet[s];
      const int a = adj.inc_local[s];
      const double V = geo.volume[t];
      const Vec3& ga = geo.grad[t][a];
      for (int b = 0; b < 4; ++b) {
        if (b == a) continue;
        const int e = slot[geo.tets[t][b]];
        const Vec3& gb = geo.grad[t][b];
        ops.A[e].noalias() += V * ga * gb.transpose();
        ops.B[e].noalias() += V * (gb * ga.transpose() + ga.dot(gb) * Mat3::Identity());
      }
    }
    slot.reset(adj, i);
  }
  return ops;
}

std::vector<Mat3> combine_edge_operators(const EdgeOperators& ops, double coefficient_a,
                                         double coefficient_b) {
  std::vector<Mat3> k(ops.A.size());
  for (size_t e = 0; e < k.size(); ++e) k[e] = coefficient_a * ops.A[e] + coefficient_b * ops.B[e];
  return k;
}

Mat3 orthotropic_block(const Vec3& ga, const Vec3& gb, double volume, double lambda,
                       const double (&mu)[3][3]) {
  Mat3 k;
  for (int p = 0; p < 3; ++p)
    for (int r = 0; r < 3; ++r) {
      double x = lambda * ga[p] * gb[r] + mu[p][r] * gb[p] * ga[r];
      if (p == r)
        for (int q = 0; q < 3; ++q) x += mu[p][q] * ga[q] * gb[q];
      k(p, r) = volume * x;
    }
  return k;
}

std::vector<Mat3> orthotropic_edge_matrices(const TetGeometry& geo, const PointAdjacency& adj,
                                            double lambda, double mu,
                                            const StiffnessScales& scales) {
  const double lam = lambda * scales.lambda;
  double m[3][3];
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) m[p][q] = mu * scales.mu[3 * p + q];
  std::vector<Mat3> k(adj.nbr.size(), Mat3::Zero());
  NeighbourSlots slot(adj.num_points());
  for (int i = 0; i < adj.num_points(); ++i) {
    slot.set(adj, i);
    for (int s = adj.inc_start[i]; s < adj.inc_start[i + 1]; ++s) {
      const int t = adj.inc_tet[s], a = adj.inc_local[s];
      for (int b = 0; b < 4; ++b)
        if (b != a)
          k[slot[geo.tets[t][b]]] +=
              orthotropic_block(geo.grad[t][a], geo.grad[t][b], geo.volume[t], lam, m);
    }
    slot.reset(adj, i);
  }
  return k;
}

Mat3 diagonal_block(const std::vector<Mat3>& k_edges, const PointAdjacency& adj, int i) {
  Mat3 d = Mat3::Zero();
  for (int e = adj.nbr_start[i]; e < adj.nbr_start[i + 1]; ++e) d -= k_edges[e];
  return d;
}

}  // namespace mrsim
