#pragma once
// The largest eigenvalue of M⁻¹A for a level's stiffness (A = K) or damping (A = D) matrix, by
// Lanczos (docs/integrators.md "Calibrated by the spectrum"). The per-point bounds of
// physics/stable_step_bound.hpp are proven but sum a whole star: max_i S_i/m_i is 2.0–2.5 times
// λ_max(M⁻¹K) on the bundled liver levels. That looseness costs √2–√2.5 in an undamped step
// but the full 2–2.5 where damping sets the step. For one global step each level therefore
// scales its point bounds by kSpectralMargin × λ_max / max_i S_i/m_i (never above 1;
// LevelModel's calibrated()): the level alone is estimated within the margin of its true limit,
// and the hierarchy's points keep their relative sizes. Time levels keep the proven bounds.
#include <vector>

#include "core/vec.hpp"
#include "physics/point_adjacency.hpp"
#include "physics/stable_step_bound.hpp"
#include "physics/tangent_growth.hpp"

namespace mrsim {

/// Kept between the largest eigenvalue of the linear model at rest and the step: Green–Lagrange
/// stiffens in tension (+32 % in ω² at 10 % stretch), and the hierarchy couples levels through
/// ghosts whose bounds are not calibrated. 1.5 in ω² is 1.22 in the undamped step.
inline constexpr double kSpectralMargin = 1.5;

/// λ_max of M^-1/2 A M^-1/2, where (A u)_i = Σ_j A_ij (u_j − u_i) over the CSR edge blocks of
/// `adj` (the sign convention of LevelModel::K and ::D; A positive semi-definite), over the
/// points of positive finite mass: give a held point an infinite mass to leave it out (holding
/// points only lowers λ_max: held at its base, liver_thesis' finest level allows a 1.69× longer
/// semi-implicit step). Lanczos from a fixed start vector (deterministic),
/// until the Ritz value's residual bound is below `tolerance` of it or after `max_iterations`;
/// returns the Ritz value plus that residual bound, so that it errs upwards. 0 for an empty
/// level or A = 0.
double largest_mass_scaled_eigenvalue(const PointAdjacency& adj, const std::vector<Mat3>& edge,
                                      const std::vector<double>& mass, double tolerance = 1e-3,
                                      int max_iterations = 300);

/// λ_max of M^-1/2 (A − 2 blockdiag A) M^-1/2 (signed: it may be negative), with A as above:
/// for A = K, the stiffness the semi-implicit filter (eq. 5.1, time/semi_implicit_filter.hpp)
/// leaves to the explicit step. The filter divides each velocity by I + dt²/m_i K_ii: a
/// kick–drift step with mass M + dt²D and damping C + dt D (D = blockdiag K), stable while
/// 4M − dt²(K − 2D) − 2dt C ⪰ 0 (docs/integrators.md "The stable step").
double largest_filtered_eigenvalue(const PointAdjacency& adj, const std::vector<Mat3>& edge,
                                   const std::vector<double>& mass, double tolerance = 1e-3,
                                   int max_iterations = 300);

/// The largest step dt of the level alone with λ_max(M⁻¹(dt² A + 2dt C)) ≤ 4, A = K or, if
/// `filtered`, K − 2 blockdiag K: the kick–drift condition 4M − dt²A − 2dt C ⪰ 0 for the whole
/// operator. Where damping and stiffness peak on different modes this is well above the step
/// from the two maxima apart (`stiffness` = λ_max(M⁻¹A), `damping` = λ_max(M⁻¹C), where the
/// search starts): 4.6 times on the liver with ψ = 5 Pa·s under the filter. Bisection to 1 %
/// from below, one Lanczos run per trial; +inf when no step is limited.
double combined_step_limit(const PointAdjacency& adj, const std::vector<Mat3>& K,
                           const std::vector<Mat3>& C, const std::vector<double>& mass,
                           bool filtered, double stiffness, double damping);

/// How a level's tet bounds are scaled (stiffness or damping).
struct SpectralScale {
  double eigenvalue = 0;  // λ_max(M⁻¹A), 1/s² (stiffness) or 1/s (damping)
  double star_max = 0;    // max_i of the point bound over the mass, same unit
  double scale = 1;       // min(1, kSpectralMargin × eigenvalue / star_max)
};

SpectralScale spectral_scale(double eigenvalue, double star_max);

/// What Green–Lagrange stiffening adds to the filtered spectrum, as a share of λ_max(M⁻¹K): the
/// filter's blocks are taken at rest and do not follow the tangent stiffness, so its whole
/// growth lands on the small λ_f. The set-up estimate assumes this share, and it is the floor
/// of the one that follows the strain (below). It was 0.2 while it also had to cover deep
/// indentations (volume_lambda_5e5 became unstable at λ_f + 0.14 λ_K of its finest level);
/// since the share follows g those are covered by kStiffeningPerGrowth, and what needs the
/// floor was the adaptive beam: without it its whole run was 0.94 (optimistic), with 0.1 1.35.
/// At 0.2 the thesis-sized liver's estimate was 2.6–3 times below its true limit, the floor
/// being 77 % of its finest level's share (docs/stability_matrix.md, 2026-11-28). What the
/// adaptive beam needed was the thesis' finite probe of the filter's blocks (its error is not
/// counted by λ_f): with the blocks K_ii (time/semi_implicit_filter.hpp) its true limit went
/// from 62 to 36 substeps and 0.1 made it 2.70 times cautious. 0.05 since 2026-12-03 (1.74; all
/// 18 bundled semi-implicit whole runs without time levels 1.16–2.39, none below 1; with no
/// floor at all 1.68, the nine others measured alike), kept for what a floor still covers: the
/// blocks do not rotate with the body.
inline constexpr double kFilterStiffening = 0.05;

/// During a run the share follows the level's largest tangent growth g (physics/
/// tangent_growth.hpp): max(kFilterStiffening, kStiffeningPerGrowth × g). Measured on the
/// indentations of docs/stability_matrix.md, instability came at a share of 0.19–0.23 g (g up
/// to 1.2 under the probe at λ = 5·10⁴, where the fixed 0.2 was 6 % optimistic); 0.3 keeps
/// the estimate below the true limit there. The floor stays: the filter's blocks do not rotate
/// with the body either, and without any the adaptive beam's whole run was 0.94.
inline constexpr double kStiffeningPerGrowth = 0.3;

/// The share of λ_K allowed for stiffening at tangent growth g.
double filter_stiffening(double growth);

/// Semi-implicit with time levels, the factor on a point's proven stiffness bound d at tangent
/// growth g, for stable_step_of() (which counts kSemiImplicitShare d): the point counts its
/// `share` of d at rest (physics/patch_spectrum.hpp; the thesis' quarter until 2026-12-03), and
/// the growth adds up to g d that the filter's blocks, taken at rest, leave explicit; of it
/// kStiffeningPerGrowth g d counts, as for the global step: (share + kStiffeningPerGrowth g) /
/// kSemiImplicitShare. Without the growth, two whole runs held at exactly courant × 1.00
/// (docs/stability_matrix.md). Explicit time levels take only explicit_stiffening(): the proven
/// bounds' slack covered g up to 1.2 (1.24–1.54).
double time_level_stiffening(double growth, double share = kSemiImplicitShare);

/// The explicit schemes, the factor on a point's stiffness bound at tangent growth g: the
/// deformed tangent is below (1 + g) times the rest bound (physics/tangent_growth.hpp), and the
/// estimate already stands for kSpectralMargin times the rest spectrum (one global step; the
/// proven bounds of time levels are looser still), so only what the margin does not cover
/// counts: max(1, (1 + g) / kSpectralMargin). Below g = 0.5 nothing changes (the bundled
/// scenarios' runs keep their steps); a soft Green–Lagrange beam hanging under gravity
/// (E = 15 kPa, ρ = 3 100 kg/m³) reached g ≈ 8 and diverged at its computed step without it.
double explicit_stiffening(double growth);

/// The same for the damping bound at damping growth g_d (1 + g_d, proven): the combined
/// limit's margin is √kSpectralMargin on the damping, so max(1, (1 + g_d) / √kSpectralMargin).
double explicit_damping_growth(double damping_growth);

/// The growths below which both factors above are 1: what tangent_growths_of() must give
/// exactly for the explicit schemes (kSpectralMargin − 1 and √kSpectralMargin − 1).
GrowthsNeeded explicit_growths_needed();

/// The semi-implicit scale of a level's stiffness bounds: its largest point bound then stands
/// for λ_f + max((kSpectralMargin − 1)|λ_f|, stiffening λ_K), with λ_f =
/// largest_filtered_eigenvalue (negative: no elastic limit), λ_K = `stiffness` and `stiffening`
/// 0 for a linear (Cauchy) law, filter_stiffening() for Green–Lagrange.
/// λ_f is 0.002–0.18 of λ_K on the bundled levels, so the filter's limit 2/√λ_f is 2.3–24
/// times the explicit one, where the thesis' rule says 2.
SpectralScale filter_scale(double filtered, double stiffness, double star_max, double stiffening);

}  // namespace mrsim
