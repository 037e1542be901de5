#include "hierarchy/level_calibration.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <optional>

#include "core/error.hpp"
#include "physics/component_stiffness.hpp"
#include "physics/lowest_modes.hpp"

namespace mrsim {

namespace {

constexpr int kModes = 6;  // frequencies fitted
// Weight of each frequency in the fit: the first two (a body's main bending) as much as a sag,
// the higher ones, which a level a few tets across cannot all follow, less.
constexpr double kModeWeight[kModes] = {2, 1, 0.3, 0.3, 0.3, 0.3};
constexpr double kPull = 0.05;     // towards the isotropic law, per log-factor
constexpr double kLogBound = 4.6;  // factors within [1/100, 100]
constexpr int kMaxIterations = 60;

using Vector = Eigen::VectorXd;
using Params = std::array<double, 7>;

// What the fit matches: log sags (held bodies) and weighted log ω of the fitted modes, with
// their derivatives with respect to the seven log-factors.
struct Response {
  Vector value;
  Eigen::MatrixXd jacobian;              // rows like value, 7 columns
  std::vector<double> sag, peak, omega;  // mean and largest displacement under unit gravity
};

Response respond(const ComponentStiffness& cs, const Params& s, bool held, int rigid) {
  const SparseMatrix K = cs.combined(s);
  const int n = cs.free_dofs();
  std::vector<Vector> loads;  // M e_d
  if (held)
    for (int d = 0; d < 3; ++d) {
      Vector f = Vector::Zero(n);
      for (int i = d; i < n; i += 3) f[i] = cs.mass[i];
      loads.push_back(f);
    }
  const int rows = static_cast<int>(loads.size()) + kModes;
  Response r;
  r.value.resize(rows);
  r.jacobian.resize(rows, 7);
  // A held level's K is positive definite: one factorisation serves the static solves and,
  // unshifted, the modes. A free one is shifted below its rigid modes (lowest_modes()).
  std::optional<SparseLdlt> solver;
  if (held) {
    solver.emplace(K);
    // LDLᵀ succeeds on a singular K (a zero pivot is just small): a level held at collinear
    // points still turns about their line, so the pivots are checked against the largest.
    const Vector d = solver->vectorD();
    if (solver->info() != Eigen::Success || !(d.minCoeff() > 1e-10 * d.maxCoeff()))
      throw InputError(
          "object.calibration: a level's fixed points do not hold it (collinear or too few: "
          "it can still move rigidly); fix points that span a plane, or none (a free body)");
    for (size_t d = 0; d < loads.size(); ++d) {
      // The mass-weighted mean displacement along the load, f·u / Σm: what a sag is, on a
      // level whose mass differs from the finest one's (independent meshes of one surface).
      const Vector u = solver->solve(loads[d]);
      const double c = loads[d].dot(u);
      r.sag.push_back(c / loads[d].sum());
      r.value[d] = std::log(c / loads[d].sum());
      for (int j = 0; j < 7; ++j) r.jacobian(d, j) = -s[j] * u.dot(cs.parts[j] * u) / c;
      // The largest displacement (a beam's tip) is reported, not fitted: on the liver it sits
      // on a thin lobe the coarse surfaces do not have, and fitting it distorted the tensor.
      double peak = 0;
      for (int i = 0; i + 2 < n; i += 3) peak = std::max(peak, u.segment<3>(i).norm());
      r.peak.push_back(peak);
    }
  }
  const Modes modes = held ? lowest_modes(*solver, 0.0, cs.mass, rigid + kModes)
                           : lowest_modes(K, cs.mass, rigid + kModes);
  const int first = static_cast<int>(loads.size());
  for (int k = 0; k < kModes; ++k) {
    const int m = std::min<int>(rigid + k, static_cast<int>(modes.omega2.size()) - 1);
    const double w2 = std::max(modes.omega2[m], 1e-300);
    const Vector phi = modes.shapes.col(m);
    r.omega.push_back(std::sqrt(w2));
    const double weight = kModeWeight[k];
    r.value[first + k] = weight * 0.5 * std::log(w2);
    for (int j = 0; j < 7; ++j)
      r.jacobian(first + k, j) = weight * s[j] * phi.dot(cs.parts[j] * phi) / (2 * w2);
  }
  return r;
}

Params factors(const Vector& p) {
  Params s;
  for (int j = 0; j < 7; ++j) s[j] = std::exp(p[j]);
  return s;
}

double cost(const Vector& residual, const Vector& p) {
  return residual.squaredNorm() + kPull * kPull * p.squaredNorm();
}

std::vector<double> ratios(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> out(a.size());
  for (size_t k = 0; k < a.size(); ++k) out[k] = a[k] / b[k];
  return out;
}

LevelCalibration fit(const ComponentStiffness& cs, const Response& target, bool held, int rigid) {
  Vector p = Vector::Zero(7);
  Response r = respond(cs, factors(p), held, rigid);
  LevelCalibration out;
  out.sag_before = ratios(r.sag, target.sag);
  out.peak_before = ratios(r.peak, target.peak);
  out.frequency_before = ratios(r.omega, target.omega);
  Vector residual = r.value - target.value;
  double c = cost(residual, p), damping = 1e-3;
  for (int it = 0; it < kMaxIterations && damping < 1e8; ++it) {
    out.iterations = it + 1;
    const Eigen::MatrixXd& J = r.jacobian;
    Eigen::MatrixXd A = J.transpose() * J;
    A.diagonal().array() += kPull * kPull;
    const Vector g = J.transpose() * residual + kPull * kPull * p;
    Eigen::MatrixXd damped = A;
    damped.diagonal() += damping * A.diagonal();
    const Vector step = (-damped.ldlt().solve(g)).cwiseMax(-1.0).cwiseMin(1.0);
    const Vector trial = (p + step).cwiseMax(-kLogBound).cwiseMin(kLogBound);
    Response rt = respond(cs, factors(trial), held, rigid);
    const Vector rest = rt.value - target.value;
    const double ct = cost(rest, trial);
    if (ct < c) {
      const bool small = (trial - p).lpNorm<Eigen::Infinity>() < 1e-5 || c - ct < 1e-12 * c;
      p = trial, r = std::move(rt), residual = rest, c = ct;
      damping = std::max(damping / 3, 1e-9);
      if (small) break;
    } else {
      damping *= 5;
    }
  }
  out.scales = StiffnessScales::from_components(factors(p));
  out.sag_after = ratios(r.sag, target.sag);
  out.peak_after = ratios(r.peak, target.peak);
  out.frequency_after = ratios(r.omega, target.omega);
  return out;
}

int held_points(const std::vector<std::uint8_t>& fixed) {
  return static_cast<int>(std::count(fixed.begin(), fixed.end(), 1));
}

}  // namespace

std::vector<LevelCalibration> calibrate_levels(
    const std::vector<const TetMesh*>& meshes, const MaterialLaw& law,
    const std::vector<std::vector<std::uint8_t>>& fixed) {
  const int levels = static_cast<int>(meshes.size());
  std::vector<LevelCalibration> out(levels);
  if (levels < 2) return out;
  int held_levels = 0;
  for (int l = 0; l < levels; ++l) {
    const int h = fixed.empty() || fixed[l].empty() ? 0 : held_points(fixed[l]);
    if (h > 0 && h < 3)
      throw InputError("object.calibration: level " + std::to_string(l) + " is held at " +
                       std::to_string(h) +
                       " point(s); calibration needs every level held at three points or more, "
                       "or a free body");
    held_levels += h > 0;
  }
  if (held_levels != 0 && held_levels != levels)
    throw InputError(
        "object.calibration: some levels are held and others are free; the fixed regions must "
        "select points on every level (or on none)");
  const bool held = held_levels == levels;
  const int rigid = held ? 0 : 6;
  auto stiffness = [&](int l) {
    const TetGeometry geo = build_tet_geometry(*meshes[l]);
    return component_stiffness(geo, static_cast<int>(meshes[l]->points.size()), law,
                               held ? fixed[l] : std::vector<std::uint8_t>{});
  };
  const Params ones = {1, 1, 1, 1, 1, 1, 1};
  const Response target = respond(stiffness(levels - 1), ones, held, rigid);
  for (int l = 0; l + 1 < levels; ++l) out[l] = fit(stiffness(l), target, held, rigid);
  return out;
}

}  // namespace mrsim
