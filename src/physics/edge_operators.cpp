#include "physics/edge_operators.hpp"

#include <algorithm>
#include <array>

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

namespace {

// fn(e, V_t, ∇N_i, ∇N_j) for every other vertex j of every tet t at point i, in the incidence
// order both sums below follow; e is j's entry in i's row, counted from the row's start (`slot`
// set for i).
template <class Fn>
void visit_row(const TetGeometry& geo, const PointAdjacency& adj, const NeighbourSlots& slot,
               int i, Fn&& fn) {
  const int first = adj.nbr_start[i];
  for (int s = adj.inc_start[i]; s < adj.inc_start[i + 1]; ++s) {
    const int t = adj.inc_tet[s];
    const int a = adj.inc_local[s];
    for (int b = 0; b < 4; ++b)
      if (b != a) fn(slot[geo.tets[t][b]] - first, geo.volume[t], geo.grad[t][a], geo.grad[t][b]);
  }
}

// Without coefficients only the weights are wanted: tr(B_ij) needs B's diagonal, not A. Each
// diagonal entry is summed by the same operations as in the whole block, in the same order, and
// the trace as Eigen's (d0 + d1) + d2: the same bits, without filling and adding 3×3 blocks.
void laplacian_weights_only(const TetGeometry& geo, const PointAdjacency& adj, int widest,
                            std::vector<double>& weights) {
  std::vector<std::array<double, 3>> diagonal(widest);
  NeighbourSlots slot(adj.num_points());
  for (int i = 0; i < adj.num_points(); ++i) {
    const int first = adj.nbr_start[i], degree = adj.nbr_start[i + 1] - first;
    std::fill_n(diagonal.begin(), degree, std::array<double, 3>{0, 0, 0});
    slot.set(adj, i);
    visit_row(geo, adj, slot, i, [&](int e, double V, const Vec3& ga, const Vec3& gb) {
      std::array<double, 3>& d = diagonal[e];
      const double dot = ga.dot(gb);
      for (int c = 0; c < 3; ++c) d[c] += V * (gb[c] * ga[c] + dot);
    });
    slot.reset(adj, i);
    for (int k = 0; k < degree; ++k)
      weights[first + k] = -((diagonal[k][0] + diagonal[k][1]) + diagonal[k][2]) / 4.0;
  }
}

}  // namespace

CombinedEdges combined_edge_operators(const TetGeometry& geo, const PointAdjacency& adj,
                                      const std::vector<std::array<double, 2>>& coefficients) {
  CombinedEdges out;
  // Each sized on its own: every entry is written below, and one sized vector copied into the
  // others would fault in and copy megabytes of uninitialised memory first.
  out.matrices.resize(coefficients.size());
  for (auto& m : out.matrices) m.resize(adj.nbr.size());
  out.laplacian_w.resize(adj.nbr.size());
  const int n = adj.num_points();
  int widest = 0;
  for (int i = 0; i < n; ++i) widest = std::max(widest, adj.nbr_start[i + 1] - adj.nbr_start[i]);
  if (coefficients.empty()) {
    laplacian_weights_only(geo, adj, widest, out.laplacian_w);
    return out;
  }
  std::vector<Mat3> row_a(widest), row_b(widest);  // A and B of one point's row
  NeighbourSlots slot(n);
  // Per point i, gather from its incident tets: entry (i, j) for every other vertex j.
  for (int i = 0; i < n; ++i) {
    const int first = adj.nbr_start[i], degree = adj.nbr_start[i + 1] - first;
    std::fill_n(row_a.begin(), degree, Mat3::Zero());
    std::fill_n(row_b.begin(), degree, Mat3::Zero());
    slot.set(adj, i);
    visit_row(geo, adj, slot, i, [&](int e, double V, const Vec3& ga, const Vec3& gb) {
      row_a[e].noalias() += V * ga * gb.transpose();
      row_b[e].noalias() += V * (gb * ga.transpose() + ga.dot(gb) * Mat3::Identity());
    });
    slot.reset(adj, i);
    for (int k = 0; k < degree; ++k) {
      for (size_t c = 0; c < coefficients.size(); ++c)
        out.matrices[c][first + k] = coefficients[c][0] * row_a[k] + coefficients[c][1] * row_b[k];
      // B_ij = (∇N_j∇N_iᵀ + (∇N_i·∇N_j) I) V summed, so trace(B_ij) = 4 Σ V ∇N_i·∇N_j.
      out.laplacian_w[first + k] = -row_b[k].trace() / 4.0;
    }
  }
  return out;
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

OrthotropicTensor orthotropic_tensor(double lambda, double mu, const StiffnessScales& scales) {
  OrthotropicTensor c{lambda * scales.lambda, {}};
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) c.mu[p][q] = mu * scales.mu[3 * p + q];
  return c;
}

std::vector<Mat3> orthotropic_edge_matrices(const TetGeometry& geo, const PointAdjacency& adj,
                                            double lambda, double mu,
                                            const StiffnessScales& scales) {
  const OrthotropicTensor level = orthotropic_tensor(lambda, mu, scales);
  std::vector<OrthotropicTensor> per_tet;  // object.calibration: per_tet
  for (const StiffnessScales& s : geo.scales) per_tet.push_back(orthotropic_tensor(lambda, mu, s));
  std::vector<Mat3> k(adj.nbr.size(), Mat3::Zero());
  NeighbourSlots slot(adj.num_points());
  for (int i = 0; i < adj.num_points(); ++i) {
    slot.set(adj, i);
    for (int s = adj.inc_start[i]; s < adj.inc_start[i + 1]; ++s) {
      const int t = adj.inc_tet[s], a = adj.inc_local[s];
      const OrthotropicTensor& c = per_tet.empty() ? level : per_tet[t];
      for (int b = 0; b < 4; ++b)
        if (b != a)
          k[slot[geo.tets[t][b]]] +=
              orthotropic_block(geo.grad[t][a], geo.grad[t][b], geo.volume[t], c.lambda, c.mu);
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
