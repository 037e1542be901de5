#include "physics/spectral_bound.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/portable_math.hpp"
#include "physics/stable_step_bound.hpp"

namespace mrsim {

namespace {

// One term of the operator: coefficient × (A u)_i = Σ_j A_ij (u_j + own u_i). own = -1 gives A,
// own = +1 gives A − 2 blockdiag(A) (the diagonal block being -Σ_j A_ij).
struct Term {
  const std::vector<Mat3>* edge;
  double own, coefficient;
};

// y = M^-1/2 (Σ terms) M^-1/2 x, one gather per point (s = 1/√m, 0 where a point has no mass).
// The terms (at most two: stiffness and damping) share one pass over each point's neighbours,
// each with its own sum: the same operations in the same order as one pass per term. sx: room
// for s x, formed once per product rather than once per neighbour visit (the same products).
constexpr std::size_t kMaxTerms = 2;

template <std::size_t N>
void apply_terms(const PointAdjacency& adj, const std::vector<Term>& terms,
                 const Eigen::VectorXd& s, const Eigen::VectorXd& x, Eigen::VectorXd& sx,
                 Eigen::VectorXd& y) {
  const int n = adj.num_points();
  std::array<const Mat3*, N> edge;
  std::array<double, N> own, coefficient;
  for (std::size_t k = 0; k < N; ++k) {
    edge[k] = terms[k].edge->data();
    own[k] = terms[k].own;
    coefficient[k] = terms[k].coefficient;
  }
  for (int i = 0; i < n; ++i) sx.segment<3>(3 * i) = s[i] * x.segment<3>(3 * i);
  for (int i = 0; i < n; ++i) {
    const Vec3 xi = sx.segment<3>(3 * i);
    std::array<Vec3, N> sum;
    for (std::size_t k = 0; k < N; ++k) sum[k].setZero();
    for (int e = adj.nbr_start[i]; e < adj.nbr_start[i + 1]; ++e) {
      const Vec3 xj = sx.segment<3>(3 * adj.nbr[e]);
      for (std::size_t k = 0; k < N; ++k) sum[k].noalias() += edge[k][e] * (xj + own[k] * xi);
    }
    Vec3 yi = Vec3::Zero();
    for (std::size_t k = 0; k < N; ++k) yi += coefficient[k] * sum[k];
    y.segment<3>(3 * i) = s[i] * yi;
  }
}

void apply(const PointAdjacency& adj, const std::vector<Term>& terms, const Eigen::VectorXd& s,
           const Eigen::VectorXd& x, Eigen::VectorXd& sx, Eigen::VectorXd& y) {
  if (terms.size() == 1)
    apply_terms<1>(adj, terms, s, x, sx, y);
  else
    apply_terms<2>(adj, terms, s, x, sx, y);
}

// Largest Ritz value of the tridiagonal (alpha, beta) and its residual bound |β_k s_k|.
std::pair<double, double> top_ritz(const std::vector<double>& alpha,
                                   const std::vector<double>& beta) {
  const int k = static_cast<int>(alpha.size());
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(k, k);
  for (int i = 0; i < k; ++i) {
    T(i, i) = alpha[i];
    if (i + 1 < k) T(i, i + 1) = T(i + 1, i) = beta[i];
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(T);
  const int top = k - 1;  // eigenvalues ascending
  return {es.eigenvalues()[top], std::abs(beta[k - 1] * es.eigenvectors()(k - 1, top))};
}

// A fixed start vector with every component non-zero and no symmetry of the mesh, normalised.
Eigen::VectorXd start_vector(int dofs) {
  Eigen::VectorXd q(dofs);
  for (int k = 0; k < dofs; ++k) q[k] = 1.0 + 0.5 * portable::sin(0.7 * k + 0.3 * (k % 7));
  return q / q.norm();
}

// Lanczos for the largest algebraic eigenvalue of M^-1/2 A M^-1/2 (A of apply()), from a fixed
// start vector; the Ritz value plus its residual bound (errs upwards). With `above`, it stops as
// soon as the largest Ritz value exceeds it and returns that value: the largest eigenvalue of the
// growing tridiagonal never decreases (Cauchy interlacing), so the full run would have returned
// more than `above` too. That test is made at every iteration (a tridiagonal of a few rows), the
// convergence test every fifth: a run that ends within `above` is the same run as without the
// test. `start`: start_vector(3 × points), when the caller runs several Lanczos runs on one
// level.
double lanczos_top(const PointAdjacency& adj, const std::vector<Term>& terms,
                   const std::vector<double>& mass, double tolerance, int max_iterations,
                   double above = std::numeric_limits<double>::infinity(),
                   const Eigen::VectorXd* start = nullptr) {
  const int n = adj.num_points(), dofs = 3 * n;
  if (terms.size() > kMaxTerms) throw std::logic_error("lanczos_top: more terms than apply() sums");
  Eigen::VectorXd s(n);
  for (int i = 0; i < n; ++i) s[i] = mass[i] > 0 ? 1 / std::sqrt(mass[i]) : 0;
  Eigen::VectorXd q = start ? *start : start_vector(dofs), q_prev = Eigen::VectorXd::Zero(dofs),
                  w(dofs), sx(dofs);
  // A held point (s = 0) is outside the operator's range: starting there too would add its
  // zero eigenvalues, which would hide a negative (filtered) top of the free points.
  if ((s.array() == 0).any()) {
    for (int i = 0; i < n; ++i)
      if (s[i] == 0) q.segment<3>(3 * i).setZero();
    if (q.norm() == 0) return 0;
    q /= q.norm();
  }
  std::vector<double> alpha, beta;
  double estimate = 0;
  for (int it = 0; it < std::min(max_iterations, dofs); ++it) {
    apply(adj, terms, s, q, sx, w);
    if (it > 0) w -= beta.back() * q_prev;
    alpha.push_back(q.dot(w));
    w -= alpha.back() * q;
    beta.push_back(w.norm());
    const bool last = it + 1 == std::min(max_iterations, dofs);
    if (it % 5 == 4 || last || beta.back() == 0) {
      const auto [theta, residual] = top_ritz(alpha, beta);
      estimate = theta + residual;
      if (theta > above) return theta;
      if (residual <= tolerance * std::abs(theta) || beta.back() == 0) break;
    } else if (above < std::numeric_limits<double>::infinity()) {
      const double theta = top_ritz(alpha, beta).first;
      if (theta > above) return theta;
    }
    q_prev.swap(q);
    q = w / beta.back();
  }
  return estimate;
}

}  // namespace

double largest_mass_scaled_eigenvalue(const PointAdjacency& adj, const std::vector<Mat3>& edge,
                                      const std::vector<double>& mass, double tolerance,
                                      int max_iterations) {
  if (adj.num_points() == 0 || edge.empty()) return 0;
  return std::max(lanczos_top(adj, {{&edge, -1.0, 1.0}}, mass, tolerance, max_iterations), 0.0);
}

double largest_filtered_eigenvalue(const PointAdjacency& adj, const std::vector<Mat3>& edge,
                                   const std::vector<double>& mass, double tolerance,
                                   int max_iterations) {
  if (adj.num_points() == 0 || edge.empty()) return 0;
  return lanczos_top(adj, {{&edge, 1.0, 1.0}}, mass, tolerance, max_iterations);
}

double combined_step_limit(const PointAdjacency& adj, const std::vector<Mat3>& K,
                           const std::vector<Mat3>& C, const std::vector<double>& mass,
                           bool filtered, double stiffness, double damping) {
  const double inf = std::numeric_limits<double>::infinity();
  // dt²λ + 2dtγ = 4 with the two maxima apart (one oscillator of unit mass): stable, since
  // λ_max is subadditive.
  auto apart = [](double lambda, double gamma) {
    PointInertia unit;
    unit.mass = 1;
    unit.stiffness = lambda;
    unit.damping = gamma;
    return stable_step_of(unit, false);
  };
  if (adj.num_points() == 0 || C.empty() || damping <= 0) return apart(stiffness, 0.0);
  const double own = filtered ? 1.0 : -1.0;
  const Eigen::VectorXd start = start_vector(3 * adj.num_points());  // one for every trial
  auto stable = [&](double dt) {
    return lanczos_top(adj, {{&K, own, dt * dt}, {&C, -1.0, 2 * dt}}, mass, 1e-3, 300, 4.0,
                       &start) <= 4.0;
  };
  double lo = apart(stiffness, damping), hi = 2 * lo;
  if (!std::isfinite(lo)) return inf;
  for (int k = 0; stable(hi); ++k) {
    if (k == 30) return inf;
    lo = hi;
    hi *= 2;
  }
  while (hi > 1.01 * lo) {
    const double mid = std::sqrt(lo * hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return lo;
}

SpectralScale spectral_scale(double eigenvalue, double star_max) {
  SpectralScale out{eigenvalue, star_max, 1.0};
  if (star_max > 0) out.scale = std::min(1.0, kSpectralMargin * eigenvalue / star_max);
  return out;
}

double filter_stiffening(double growth) {
  return std::max(kFilterStiffening, kStiffeningPerGrowth * growth);
}

double time_level_stiffening(double growth, double share) {
  return (share + kStiffeningPerGrowth * std::max(0.0, growth)) / kSemiImplicitShare;
}

GrowthsNeeded explicit_growths_needed() {
  return {kSpectralMargin - 1, std::sqrt(kSpectralMargin) - 1};
}

// Compared with the thresholds themselves, so that a growth reported as a bound below them
// (tangent_growths_of()) gives the same factor, 1, as its exact value.
double explicit_stiffening(double growth) {
  const double covered = explicit_growths_needed().stiffness_above;
  return growth <= covered ? 1.0 : (1.0 + growth) / kSpectralMargin;
}

double explicit_damping_growth(double damping_growth) {
  const double covered = explicit_growths_needed().damping_above;
  return damping_growth <= covered ? 1.0 : (1.0 + damping_growth) / std::sqrt(kSpectralMargin);
}

SpectralScale filter_scale(double filtered, double stiffness, double star_max, double stiffening) {
  SpectralScale out{filtered, star_max, 1.0};
  const double margin =
      std::max((kSpectralMargin - 1) * std::abs(filtered), stiffening * stiffness);
  const double with_margin = filtered + margin;
  if (star_max > 0) out.scale = with_margin / (kSemiImplicitShare * star_max);
  return out;
}

}  // namespace mrsim
