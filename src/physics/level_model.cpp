#include "physics/level_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "physics/lumped_mass.hpp"
#include "physics/patch_spectrum.hpp"

namespace mrsim {

namespace {

void edge_lengths(LevelModel& m) {
  const int n = m.num_points();
  m.mean_edge.assign(n, 0.0);
  m.min_edge.assign(n, std::numeric_limits<double>::infinity());
  for (int i = 0; i < n; ++i) {
    double sum = 0;
    for (int e = m.adj.nbr_start[i]; e < m.adj.nbr_start[i + 1]; ++e) {
      const double l = (m.mesh->points[m.adj.nbr[e]] - m.mesh->points[i]).norm();
      sum += l;
      m.min_edge[i] = std::min(m.min_edge[i], l);
    }
    m.mean_edge[i] = sum / std::max(1, m.adj.degree(i));
  }
}

// The damping scale at which the level's smallest point step, its stiffness bounds scaled by
// `stiffness_scale`, is `target`, never above the damping spectrum's own scale. A point's step
// falls as its damping grows, in floating point too (every operation of stable_step_of is
// monotone), so only the points whose step at the spectrum's scale is at most the smallest
// undamped step can be the smallest at a scale between: the bisection takes its minima over
// them alone, the same values. O(points) twice, then O(those points) per trial.
double combined_damping_scale(const LevelModel& m, bool semi, double target,
                              double stiffness_scale, const std::vector<double>& point_scale = {}) {
  const double own = m.damping_spectrum.scale;
  if (!std::isfinite(target)) return own;
  std::vector<PointInertia> points;  // free points, their stiffness scaled
  points.reserve(m.num_points());
  for (int i = 0; i < m.num_points(); ++i)
    if (!is_held(m, i)) {
      points.push_back(m.star[i]);
      points.back().stiffness *= stiffness_scale * (point_scale.empty() ? 1.0 : point_scale[i]);
    }
  auto step = [&](PointInertia p, double damping_scale) {
    p.damping *= damping_scale;
    return stable_step_of(p, semi);
  };
  auto smallest_step = [&](double damping_scale) {
    double dt = std::numeric_limits<double>::infinity();
    for (const PointInertia& p : points) dt = std::min(dt, step(p, damping_scale));
    return dt;
  };
  if (!(target > smallest_step(own))) return own;
  const double undamped = smallest_step(0.0);
  if (undamped <= target) return 0.0;
  std::erase_if(points, [&](const PointInertia& p) { return step(p, own) > undamped; });
  double lo = 0.0, hi = own;  // smallest step above the target at lo, below at hi
  while (hi - lo > 1e-3 * own) {
    const double mid = 0.5 * (lo + hi);
    (smallest_step(mid) > target ? lo : hi) = mid;
  }
  return hi;
}

// The masses the spectra see: a held point's is infinite, which takes it out of the operator.
std::vector<double> spectral_masses(const LevelModel& m) {
  std::vector<double> mass = m.mass;
  for (int i = 0; i < m.num_points(); ++i)
    if (is_held(m, i)) mass[i] = std::numeric_limits<double>::infinity();
  return mass;
}

// The level's Lanczos runs (physics/spectral_bound.hpp) over its free points.
LevelSpectra measured_spectra(const LevelModel& m, bool semi_implicit) {
  const std::vector<double> mass = spectral_masses(m);
  LevelSpectra s;
  s.stiffness = largest_mass_scaled_eigenvalue(m.adj, m.K, mass);
  s.damping = largest_mass_scaled_eigenvalue(m.adj, m.D, mass);
  if (semi_implicit) s.filtered = largest_filtered_eigenvalue(m.adj, m.K, mass);
  if (m.D.empty() || m.num_points() == 0) return s;
  s.combined = combined_step_limit(m.adj, m.K, m.D, mass, semi_implicit,
                                   semi_implicit ? s.filtered : s.stiffness, s.damping);
  return s;
}

// The level's spectra against their largest point bounds (physics/spectral_bound.hpp).
void apply_spectra(LevelModel& m, bool semi_implicit, const LevelSpectra& s) {
  double k_max = 0, c_max = 0;
  for (int i = 0; i < m.num_points(); ++i) {
    const PointInertia& p = m.star[i];
    if (p.mass > 0 && !is_held(m, i)) {
      k_max = std::max(k_max, p.stiffness / p.mass);
      c_max = std::max(c_max, p.damping / p.mass);
    }
  }
  m.combined_limit = s.combined;
  m.stiffness_spectrum = spectral_scale(s.stiffness, k_max);
  m.damping_spectrum = spectral_scale(s.damping, c_max);
  m.step_damping_scale = m.time_level_damping_scale = m.damping_spectrum.scale;
  if (semi_implicit)
    m.filter_spectrum = filter_scale(s.filtered, m.stiffness_spectrum.eigenvalue, k_max,
                                     stiffens(m) ? kFilterStiffening : 0.0);
  if (!m.law.damped() || m.num_points() == 0) return;
  // The level's combined limit (damping and stiffness modes apart) over √kSpectralMargin.
  const SpectralScale& k = semi_implicit ? m.filter_spectrum : m.stiffness_spectrum;
  const double target = s.combined / std::sqrt(kSpectralMargin);
  m.step_damping_scale = combined_damping_scale(m, semi_implicit, target, k.scale);
  m.time_level_damping_scale = combined_damping_scale(m, semi_implicit, target, 1.0);
}

}  // namespace

void prepare_semi_implicit_time_levels(LevelModel& m) {
  if (!m.time_level_share.empty() || m.num_points() == 0) return;
  if (m.K.empty()) throw std::logic_error("prepare_semi_implicit_time_levels: no edge matrices");
  m.time_level_share = time_level_filter_shares(
      m.adj, patch_filtered_eigenvalues(m.adj, m.K, spectral_masses(m)), m.star);
  raise_to_level_share(m.time_level_share, m.filter_spectrum.eigenvalue,
                       m.stiffness_spectrum.star_max);
  if (!m.law.damped()) return;
  // The damping scale of time levels against the stiffness they now count.
  std::vector<double> factor = m.time_level_share;
  for (double& f : factor) f /= kSemiImplicitShare;
  m.time_level_damping_scale = combined_damping_scale(
      m, true, m.combined_limit / std::sqrt(kSpectralMargin), 1.0, factor);
}

double time_level_share(const LevelModel& m, int point) {
  if (point < 0) return kSemiImplicitShare;
  if (m.time_level_share.empty())
    throw std::logic_error("time_level_share: prepare_semi_implicit_time_levels() not called");
  return m.time_level_share[point];
}

bool stiffens(const LevelModel& m) { return m.law.strain == StrainMeasure::GreenLagrange; }

SpectralScale filter_spectrum_at(const LevelModel& m, double growth) {
  if (!stiffens(m)) return m.filter_spectrum;
  return filter_scale(m.filter_spectrum.eigenvalue, m.stiffness_spectrum.eigenvalue,
                      m.filter_spectrum.star_max, filter_stiffening(growth));
}

PointInertia calibrated(PointInertia p, const LevelModel& m, bool semi_implicit, bool time_levels,
                        double growth, double damping_growth, int point) {
  if (semi_implicit) {
    p.damping *= 1.0 + std::max(0.0, damping_growth);
  } else {
    p.stiffness *= explicit_stiffening(growth);
    p.damping *= explicit_damping_growth(damping_growth);
  }
  if (time_levels) {
    if (semi_implicit) p.stiffness *= time_level_stiffening(growth, time_level_share(m, point));
    p.damping *= m.time_level_damping_scale;
    return p;
  }
  if (semi_implicit)
    p.stiffness *= growth == 0 ? m.filter_spectrum.scale : filter_spectrum_at(m, growth).scale;
  else
    p.stiffness *= m.stiffness_spectrum.scale;
  p.damping *= m.step_damping_scale;
  return p;
}

LevelSpectra level_spectra(const LevelModel& m) {
  return {m.stiffness_spectrum.eigenvalue, m.damping_spectrum.eigenvalue,
          m.filter_spectrum.eigenvalue, m.combined_limit};
}

bool edge_matrices_needed(const MaterialLaw& law, bool semi_implicit) {
  return law.strain == StrainMeasure::Cauchy || semi_implicit;
}

LevelModel build_level_model(const TetMesh& mesh, const MaterialLaw& law, bool semi_implicit,
                             const std::vector<std::uint8_t>& held, const LevelSpectra* known,
                             LevelArrays* arrays) {
  LevelModel m;
  m.mesh = &mesh;
  m.law = law;
  if (!held.empty() && held.size() != mesh.points.size())
    throw std::logic_error("build_level_model: a held mask of another level");
  if (std::find(held.begin(), held.end(), 1) != held.end()) m.held = held;
  m.geo = build_tet_geometry(mesh, &law);
  m.adj = arrays ? std::move(arrays->adj)
                 : build_point_adjacency(static_cast<int>(mesh.points.size()), mesh.tets);
  m.mass = lumped_masses(m.geo, m.adj, law.density);
  m.lumped_volume = lumped_masses(m.geo, m.adj, 1.0);
  // K = λA + μB and D = φA + ψB of the isotropic law come with the Laplacian weights; a
  // calibrated level (hierarchy/level_calibration.hpp) takes only the weights from there.
  const bool matrices = !known || edge_matrices_needed(law, semi_implicit);
  // Per-tet tensors (object.calibration: per_tet) go the orthotropic way, which takes each tet's
  // scales (TetGeometry::scales); the weights stay the geometric ones.
  const bool isotropic = law.scales.isotropic() && !law.tet_tensors;
  if (arrays && !matrices) {
    m.laplacian_w = std::move(arrays->laplacian_w);  // the weights alone: the same bits
  } else {
    std::vector<std::array<double, 2>> coefficients;
    if (matrices && isotropic) coefficients.push_back({law.lambda, law.mu});
    if (matrices && isotropic && law.damped()) coefficients.push_back({law.phi, law.psi});
    CombinedEdges edges = combined_edge_operators(m.geo, m.adj, coefficients);
    m.laplacian_w = std::move(edges.laplacian_w);
    if (!matrices) {
      // K and D would only feed the spectra, which are known.
    } else if (isotropic) {
      m.K = std::move(edges.matrices[0]);
      if (law.damped()) m.D = std::move(edges.matrices[1]);
    } else {
      m.K = orthotropic_edge_matrices(m.geo, m.adj, law.lambda, law.mu, law.scales);
      if (law.damped())
        m.D = orthotropic_edge_matrices(m.geo, m.adj, law.phi, law.psi, law.scales);
    }
  }
  edge_lengths(m);
  m.bounds = arrays ? std::move(arrays->bounds) : tet_energy_bounds(m.geo, law);
  m.star = star_inertia(m.adj, m.bounds, m.mass);
  apply_spectra(m, semi_implicit, known ? *known : measured_spectra(m, semi_implicit));
  return m;
}

}  // namespace mrsim
