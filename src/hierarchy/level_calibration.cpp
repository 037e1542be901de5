#include "hierarchy/level_calibration.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <memory>

#include "core/portable_math.hpp"
#include "core/error.hpp"
#include "hierarchy/calibration_loads.hpp"
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
// per_tet: each tet's seven log-factors are pulled towards the level's tensor less than the
// level's towards the law, and no component of any tet's tensor exceeds 5 times the law's: a
// stiffer tet shortens the level's stable step (by √5 at most), a softer one does not. The pull
// trades the level alone against the level among others (the beam, docs/hierarchy.md "Per-tet
// tensors"): 0.01 fits every level alone closest but lets factors compensate one another across
// the level, which a level that is only partly simulated does not reproduce (beam_adaptive with
// coarsen_below 1e-4: 0.98 of the peak off its finest level); 0.02 keeps every bundled level
// alone within 5 % and that run at 0.14; 0.05 and more lose the local loads.
constexpr double kTetPull = 0.02;
// per_tet: the peaks, which issue 16 measures a level by with f1, weigh twice (f1 already does).
constexpr double kPeakWeight = 2.0;
constexpr double kMaxStiffening = 5.0;
// per_tet's local loads (hierarchy/calibration_loads.hpp): twelve patches of radius 5 % of the
// finest level's diagonal, each compliance weighted 0.5 (twelve of them against three sags).
// They are kept on a level only when its sags, peaks and f1 stay within kLocalKeeps of the
// finest level's: a level a few tets across cannot take a patch load as the finest does, and
// chasing it would wreck its global response (the thesis liver's 32-tet L0: f1 −23 %).
constexpr int kLocalLoads = 12;
constexpr double kLocalRadius = 0.05;
constexpr double kLocalWeight = 0.5;
constexpr double kLocalKeeps = 0.05;

using Vector = Eigen::VectorXd;
using Params = std::array<double, 7>;

// What the fit matches: log sags (held bodies), per_tet also log peaks, and weighted log ω of
// the fitted modes, with their derivatives with respect to the log-factors (the level's seven,
// then seven per tet with per_tet).
struct Response {
  Vector value;
  Eigen::MatrixXd jacobian;              // rows like value, one column per log-factor
  std::vector<double> sag, peak, omega;  // mean and largest displacement under unit gravity
  std::vector<double> local;             // compliance fᵀK⁻¹f under each local load
};

// What a held level is probed with besides its own weight (free DoFs): per_tet's local loads,
// and the weights of the mean displacement along x, y, z taken at the finest level's points
// (each point's mass share, carried to this level's points by barycentric weights; empty: the
// level's own masses, the level-wide fit's sag). A coarse level's lumped masses weigh its
// few points unlike the body's volume: one tet across the beam, a cantilever's exact deflection
// at L0's nodes averages 1.24 times the body's mean with them, 1.03 times at the finest points.
struct Probes {
  std::vector<Vector> local;
  std::vector<Vector> mean;
};

Params factors(const Vector& x) {
  Params s;
  for (int j = 0; j < 7; ++j) s[j] = portable::exp(x[j]);
  return s;
}

// per_tet: seven log-factors per tet after the level's seven, tet t's component j at 7 + 7t + j.
Eigen::Index tet_index(std::size_t t, int j) { return 7 + 7 * static_cast<Eigen::Index>(t) + j; }

TetTensors tet_factors(const Vector& x) {
  TetTensors p((x.size() - 7) / 7);
  for (size_t t = 0; t < p.size(); ++t)
    for (int j = 0; j < 7; ++j) p[t][j] = portable::exp(x[tet_index(t, j)]);
  return p;
}

// ∂(aᵀK b)/∂x of K(s, p) = Σ_t Σ_j s_j p_tj K_tj at log-factors x: Σ_t s_j p_tj (aᵀK_tj b)
// for the level's seven, s_j p_tj (aᵀK_tj b) for tet t's, written into `row` times `factor`.
void tet_derivatives(const ComponentStiffness& cs, const Params& s, const TetTensors& p,
                     const Vector& a, const Vector& b, double factor,
                     Eigen::Ref<Eigen::RowVectorXd, 0, Eigen::InnerStride<>> row) {
  const std::vector<ComponentValues> terms = cs.tet_terms(a, b);
  row.setZero();
  for (size_t t = 0; t < terms.size(); ++t)
    for (int j = 0; j < 7; ++j) {
      const double x = factor * (p[t][j] * s[j] * terms[t][j]);
      row[j] += x;
      row[tet_index(t, j)] = x;
    }
}

// A held level's K factorised: LDLᵀ succeeds on a singular K (a zero pivot is just small), and
// a level held at collinear points still turns about their line, so the pivots are checked
// against the largest.
void factorise_held(SparseLdlt& solver, const SparseMatrix& K) {
  solver.compute(K);
  const Vector d = solver.vectorD();
  if (solver.info() != Eigen::Success || !(d.minCoeff() > 1e-10 * d.maxCoeff()))
    throw InputError(
        "object.calibration: a level's fixed points do not hold it (collinear or too few: "
        "it can still move rigidly); fix points that span a plane, or none (a free body)");
}

// The static rows of a held level under unit gravity along x, y, z: its sags, then (per_tet)
// its largest displacements.
void static_rows(const ComponentStiffness& cs, const SparseLdlt& solver, const Params& s,
                 const TetTensors& p, const std::vector<Vector>& mean, Response& r) {
  const int n = cs.free_dofs();
  const bool per_tet = !p.empty();
  for (int d = 0; d < 3; ++d) {
    Vector f = Vector::Zero(n);  // M e_d
    for (int i = d; i < n; i += 3) f[i] = cs.mass[i];
    const Vector u = solver.solve(f);
    // The sag: the mass-weighted mean displacement along the load. per_tet takes it at the
    // finest level's points (Probes::mean), ∂(aᵀu) = −(K⁻¹a)ᵀ ∂K u (adjoint); the level-wide
    // fit as f·u / Σm with the level's own masses, which differ from the finest one's
    // (independent meshes of one surface).
    if (!mean.empty()) {
      const double sag = mean[d].dot(u);
      r.sag.push_back(sag);
      r.value[d] = portable::log(sag);
      tet_derivatives(cs, s, p, solver.solve(mean[d]), u, -1 / sag, r.jacobian.row(d));
    } else {
      const double c = f.dot(u);
      r.sag.push_back(c / f.sum());
      r.value[d] = portable::log(c / f.sum());
      if (per_tet)
        tet_derivatives(cs, s, p, u, u, -1 / c, r.jacobian.row(d));
      else
        for (int j = 0; j < 7; ++j) r.jacobian(d, j) = -s[j] * u.dot(cs.parts[j] * u) / c;
    }
    // The largest displacement (a beam's tip): reported by the level-wide fit, not fitted (on
    // the liver it sits on a thin lobe the coarse surfaces do not have, and one tensor for
    // the whole level could not follow it); per_tet fits it too.
    double peak = 0;
    int at = 0;
    for (int i = 0; i + 2 < n; i += 3) {
      const double norm = u.segment<3>(i).norm();
      if (norm > peak) peak = norm, at = i;
    }
    r.peak.push_back(peak);
    if (per_tet) {
      // ∂|u_P| = (u_P/|u_P|)·∂u = −aᵀ ∂K u with K a = the unit vector at P (the adjoint).
      Vector e = Vector::Zero(n);
      e.segment<3>(at) = u.segment<3>(at) / peak;
      const Vector a = solver.solve(e);
      r.value[3 + d] = kPeakWeight * portable::log(peak);
      tet_derivatives(cs, s, p, a, u, -kPeakWeight / peak, r.jacobian.row(3 + d));
    }
  }
}

// The weighted log ω rows of the fitted modes, from row `first` on.
void mode_rows(const ComponentStiffness& cs, const Modes& modes, int rigid, int first,
               const Params& s, const TetTensors& p, Response& r) {
  for (int k = 0; k < kModes; ++k) {
    const int m = std::min<int>(rigid + k, static_cast<int>(modes.omega2.size()) - 1);
    const double w2 = std::max(modes.omega2[m], 1e-300);
    const Vector phi = modes.shapes.col(m);
    r.omega.push_back(std::sqrt(w2));
    const double weight = kModeWeight[k];
    r.value[first + k] = weight * 0.5 * portable::log(w2);
    if (!p.empty())
      tet_derivatives(cs, s, p, phi, phi, weight / (2 * w2), r.jacobian.row(first + k));
    else
      for (int j = 0; j < 7; ++j)
        r.jacobian(first + k, j) = weight * s[j] * phi.dot(cs.parts[j] * phi) / (2 * w2);
  }
}

// The weighted log-compliance rows of the local loads (free DoFs), from row `first` on.
void local_rows(const ComponentStiffness& cs, const SparseLdlt& solver, const Params& s,
                const TetTensors& p, const std::vector<Vector>& loads, int first,
                Response& r) {
  for (std::size_t k = 0; k < loads.size(); ++k) {
    const Vector u = solver.solve(loads[k]);
    const double c = loads[k].dot(u);
    r.local.push_back(c);
    const int row = first + static_cast<int>(k);
    r.value[row] = kLocalWeight * portable::log(c);
    tet_derivatives(cs, s, p, u, u, -kLocalWeight / c, r.jacobian.row(row));
  }
}

Response respond(const ComponentStiffness& cs, const Vector& x, bool held, int rigid,
                 const Probes& probes) {
  const std::vector<Vector>& local = probes.local;
  const Params s = factors(x);
  const bool per_tet = x.size() > 7;
  const TetTensors p = per_tet ? tet_factors(x) : TetTensors{};
  const SparseMatrix K = per_tet ? cs.combined(s, p) : cs.combined(s);
  const int statics = held ? (per_tet ? 6 : 3) : 0;
  const int rows = statics + kModes + static_cast<int>(local.size());
  Response r;
  r.value.resize(rows);
  r.jacobian.resize(rows, x.size());
  if (!held) {  // shifted below its rigid modes (lowest_modes())
    mode_rows(cs, lowest_modes(K, cs.mass, rigid + kModes), rigid, statics, s, p, r);
    return r;
  }
  // Positive definite: one factorisation serves the static solves and, unshifted, the modes.
  SparseLdlt solver;
  factorise_held(solver, K);
  static_rows(cs, solver, s, p, probes.mean, r);
  mode_rows(cs, lowest_modes(solver, 0.0, cs.mass, rigid + kModes), rigid, statics, s, p, r);
  local_rows(cs, solver, s, p, local, statics + kModes, r);
  return r;
}

// The pull of each log-factor towards the level's isotropic law.
Vector pulls(Eigen::Index size) {
  Vector w = Vector::Constant(size, kTetPull);
  w.head(7).setConstant(kPull);
  return w;
}

double cost(const Vector& residual, const Vector& x) {
  if (x.size() == 7) return residual.squaredNorm() + kPull * kPull * x.squaredNorm();
  return residual.squaredNorm() + pulls(x.size()).cwiseProduct(x).squaredNorm();
}

std::vector<double> ratios(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> out(a.size());
  for (size_t k = 0; k < a.size(); ++k) out[k] = a[k] / b[k];
  return out;
}

// The Levenberg–Marquardt step of the seven level factors (the normal equations, 7 × 7).
Vector level_step(const Eigen::MatrixXd& J, const Vector& residual, const Vector& x,
                  double damping) {
  Eigen::MatrixXd A = J.transpose() * J;
  A.diagonal().array() += kPull * kPull;
  const Vector g = J.transpose() * residual + kPull * kPull * x;
  Eigen::MatrixXd damped = A;
  damped.diagonal() += damping * A.diagonal();
  return (-damped.ldlt().solve(g)).cwiseMax(-1.0).cwiseMin(1.0);
}

// The same with factors per tet: (JᵀJ + D) δ = −g with D diagonal (the pulls and the damping
// of diag(JᵀJ + pulls)) is solved through the rows' small system, (D + JᵀJ)⁻¹ =
// D⁻¹ − D⁻¹Jᵀ(I + J D⁻¹Jᵀ)⁻¹J D⁻¹ (Woodbury): a dozen rows against thousands of columns.
Vector tet_step(const Eigen::MatrixXd& J, const Vector& residual, const Vector& x,
                double damping) {
  const Vector w = pulls(x.size()).cwiseAbs2();
  const Vector g = J.transpose() * residual + w.cwiseProduct(x);
  const Vector D = w + damping * (J.colwise().squaredNorm().transpose() + w);
  const Vector Dg = g.cwiseQuotient(D);
  const Eigen::MatrixXd JD = J * D.cwiseInverse().asDiagonal();
  Eigen::MatrixXd small = JD * J.transpose();
  small.diagonal().array() += 1;
  const Vector step = -(Dg - JD.transpose() * small.ldlt().solve(J * Dg));
  return step.cwiseMax(-1.0).cwiseMin(1.0);
}

// Factors within [1/100, 100]; per tet also no component above kMaxStiffening.
Vector bounded(Vector x) {
  x = x.cwiseMax(-kLogBound).cwiseMin(kLogBound);
  if (x.size() == 7) return x;
  const double top = portable::log(kMaxStiffening);
  x.head(7) = x.head(7).cwiseMin(top);
  for (std::size_t t = 0; t < static_cast<std::size_t>(x.size() - 7) / 7; ++t)
    for (int j = 0; j < 7; ++j) x[tet_index(t, j)] = std::min(x[tet_index(t, j)], top - x[j]);
  return x;
}

struct Fitted {
  Vector x;
  Response r;
  int iterations = 0;
};

// Levenberg–Marquardt from the level's own law on the rows `probes` gives (no local loads: the
// global rows alone); the target's rows beyond them are not looked at.
Fitted minimise(const ComponentStiffness& cs, const Response& target, bool per_tet, bool held,
                int rigid, const Probes& local) {
  Fitted f{Vector::Zero(per_tet ? 7 + 7 * cs.num_tets() : 7), {}, 0};
  f.r = respond(cs, f.x, held, rigid, local);
  const Vector goal = target.value.head(f.r.value.size());
  Vector residual = f.r.value - goal;
  double c = cost(residual, f.x), damping = 1e-3;
  for (int it = 0; it < kMaxIterations && damping < 1e8; ++it) {
    f.iterations = it + 1;
    const Vector step = per_tet ? tet_step(f.r.jacobian, residual, f.x, damping)
                                : level_step(f.r.jacobian, residual, f.x, damping);
    const Vector trial = bounded(f.x + step);
    Response rt = respond(cs, trial, held, rigid, local);
    const Vector rest = rt.value - goal;
    const double ct = cost(rest, trial);
    if (ct < c) {
      const bool small = (trial - f.x).lpNorm<Eigen::Infinity>() < 1e-5 || c - ct < 1e-12 * c;
      f.x = trial, f.r = std::move(rt), residual = rest, c = ct;
      damping = std::max(damping / 3, 1e-9);
      if (small) break;
    } else {
      damping *= 5;
    }
  }
  return f;
}

// Are the level's sags, peaks and f1 within `band` of the finest level's?
bool global_within(const Response& r, const Response& target, double band) {
  auto near = [band](const std::vector<double>& a, const std::vector<double>& b, std::size_t n) {
    for (std::size_t k = 0; k < n && k < a.size(); ++k)
      if (std::abs(a[k] / b[k] - 1) > band) return false;
    return true;
  };
  return near(r.sag, target.sag, 3) && near(r.peak, target.peak, 3) &&
         near(r.omega, target.omega, 1);
}

// `probes`: per_tet's local loads on this level (free DoFs), kept only if the global targets
// still hold with them (kLocalKeeps), and its mean weights.
LevelCalibration fit(const ComponentStiffness& cs, const Response& target, CalibrationKind kind,
                     bool held, int rigid, const Probes& local) {
  const bool per_tet = kind == CalibrationKind::PerTet;
  LevelCalibration out;
  const Response before = respond(cs, Vector::Zero(per_tet ? 7 + 7 * cs.num_tets() : 7), held,
                                  rigid, local);
  out.sag_before = ratios(before.sag, target.sag);
  out.peak_before = ratios(before.peak, target.peak);
  out.frequency_before = ratios(before.omega, target.omega);
  out.local_before = ratios(before.local, target.local);
  Fitted f = minimise(cs, target, per_tet, held, rigid, local);
  out.local_fitted = !local.local.empty() && global_within(f.r, target, kLocalKeeps);
  if (!local.local.empty() && !out.local_fitted) {
    f = minimise(cs, target, per_tet, held, rigid, {{}, local.mean});
    f.r.local = respond(cs, f.x, held, rigid, local).local;  // reported, not fitted
  }
  out.iterations = f.iterations;
  out.scales = StiffnessScales::from_components(factors(f.x));
  if (per_tet) out.tet_tensors = tet_factors(f.x);
  out.sag_after = ratios(f.r.sag, target.sag);
  out.peak_after = ratios(f.r.peak, target.peak);
  out.frequency_after = ratios(f.r.omega, target.omega);
  out.local_after = ratios(f.r.local, target.local);
  return out;
}

// Vectors over a level's points (3 per point) restricted to its free DoFs.
std::vector<Vector> free_dofs(const std::vector<Vector>& at_points, const ComponentStiffness& cs) {
  std::vector<Vector> out;
  for (const Vector& f : at_points) {
    Vector free = Vector::Zero(cs.free_dofs());
    for (std::size_t i = 0; i < cs.dof_of_point.size(); ++i)
      if (cs.dof_of_point[i] >= 0)
        free.segment<3>(cs.dof_of_point[i]) = f.segment<3>(3 * static_cast<Eigen::Index>(i));
    out.push_back(std::move(free));
  }
  return out;
}

// The finest level's mean-displacement weights along x, y, z (3 per point): each free point's
// mass over the free mass.
std::vector<Vector> mean_weights(const ComponentStiffness& finest) {
  const Eigen::Index n = static_cast<Eigen::Index>(finest.dof_of_point.size());
  double total = 0;
  for (Eigen::Index i = 0; i < finest.free_dofs(); i += 3) total += finest.mass[i];
  std::vector<Vector> out(3, Vector::Zero(3 * n));
  for (Eigen::Index i = 0; i < n; ++i)
    if (const int dof = finest.dof_of_point[i]; dof >= 0)
      for (int d = 0; d < 3; ++d) out[d][3 * i + d] = finest.mass[dof + d] / total;
  return out;
}

// per_tet's probes of a level (none for a free body or the level-wide fit): the local loads and
// the mean weights at the finest points, carried to the level in one pass (one locator).
Probes level_probes(const std::vector<LocalLoad>& loads, const std::vector<Vector>& means,
                    const TetMesh& finest, const TetMesh& level, const ComponentStiffness& cs) {
  std::vector<Vector> fine = point_forces(loads, finest);
  fine.insert(fine.end(), means.begin(), means.end());
  std::vector<Vector> at_level = free_dofs(to_level(fine, finest, level), cs);
  const auto split = at_level.begin() + static_cast<std::ptrdiff_t>(loads.size());
  return {{at_level.begin(), split}, {split, at_level.end()}};
}

int held_points(const std::vector<std::uint8_t>& fixed) {
  return static_cast<int>(std::count(fixed.begin(), fixed.end(), 1));
}

}  // namespace

std::array<double, 2> LevelCalibration::tet_factor_range() const {
  if (tet_tensors.empty()) return {1, 1};
  std::array<double, 2> r = {tet_tensors[0][0], tet_tensors[0][0]};
  for (const auto& q : tet_tensors)
    for (double x : q) r = {std::min(r[0], x), std::max(r[1], x)};
  return r;
}

MaterialLaw LevelCalibration::applied_to(MaterialLaw law) const {
  law.scales = scales;
  if (!tet_tensors.empty()) law.tet_tensors = std::make_shared<const TetTensors>(tet_tensors);
  return law;
}

std::vector<LevelCalibration> calibrate_levels(
    const std::vector<const TetMesh*>& meshes, const MaterialLaw& law,
    const std::vector<std::vector<std::uint8_t>>& fixed, CalibrationKind kind) {
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
  if (kind == CalibrationKind::None) return out;
  // The finest level's responses: its own law (all log-factors 0), its peaks with per_tet.
  const ComponentStiffness finest = stiffness(levels - 1);
  const TetMesh& fine = *meshes[levels - 1];
  std::vector<LocalLoad> loads;
  std::vector<Vector> means;
  if (kind == CalibrationKind::PerTet && held) {
    loads = local_loads(fine, fixed[levels - 1], kLocalLoads, kLocalRadius * bbox_diagonal(fine));
    means = mean_weights(finest);
  }
  Vector at_law = Vector::Zero(kind == CalibrationKind::PerTet ? 7 + 7 * finest.num_tets() : 7);
  const Response target =
      respond(finest, at_law, held, rigid, level_probes(loads, means, fine, fine, finest));
  for (int l = 0; l + 1 < levels; ++l) {
    const ComponentStiffness cs = stiffness(l);
    out[l] = fit(cs, target, kind, held, rigid, level_probes(loads, means, fine, *meshes[l], cs));
  }
  return out;
}

}  // namespace mrsim
