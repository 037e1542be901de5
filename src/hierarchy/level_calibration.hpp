#pragma once
// Calibrated coarse levels (numerical coarsening; docs/hierarchy.md "Calibrated levels").
// Linear tets a few elements across are stiffer than the object they mesh, so each coarse level
// alone answers unlike the finest one, and an adaptive run is only as good as the region that
// refines (issue 16). Each coarser level gets an orthotropic tensor (MaterialLaw::scales: seven
// positive factors on λ and on the μ of the strain components xx, yy, zz, yz, xz, xy; the
// damping takes the same factors) fitted so that the level alone reproduces the finest level's
//   - static sag under gravity along x, y and z (the mass-weighted mean displacement f·u / Σm,
//     f = M g), when it is held, and
//   - six lowest eigenfrequencies (after the six rigid modes of a free body),
// in the log of each ratio, by Levenberg–Marquardt on the seven log-factors with analytic
// derivatives (∂ log(f·u)/∂p_j = −s_j uᵀK_j u / f·u, ∂ log ω_k/∂p_j = s_j φ_kᵀK_jφ_k / 2ω_k²)
// and a small pull towards the isotropic law. Linear (Cauchy) stiffness at rest: the fitted
// tensor then serves either strain measure (Green–Lagrange with any constant tensor stays free
// of force in a rigid motion). Kharevych et al. 2009 fit a tensor per element from harmonic
// displacements; that corrects inhomogeneity, not the locking of a homogeneous coarse mesh,
// which is what the bundled levels need — hence a fit to the finest level's responses.
#include <array>
#include <cstdint>
#include <vector>

#include "hierarchy/calibration_kind.hpp"
#include "mesh/tet_mesh.hpp"
#include "physics/material_law.hpp"

namespace mrsim {

struct LevelCalibration {
  StiffnessScales scales;  // all ones on the finest level
  // CalibrationKind::PerTet: seven factors per tet of the level on top of `scales` (empty: none).
  TetTensors tet_tensors;
  /// The smallest and largest of the per-tet factors, any component ({1, 1} without them).
  std::array<double, 2> tet_factor_range() const;
  /// `law` as this level simulates it: the level's scales and, with PerTet, its tets' tensors.
  MaterialLaw applied_to(MaterialLaw law) const;
  // The level alone against the finest level, before and after the fit (ratios): mean and
  // largest displacement under gravity along x, y, z (empty for a free body; the largest is
  // fitted by PerTet only) and the six lowest frequencies.
  std::vector<double> sag_before, sag_after, peak_before, peak_after;
  std::vector<double> frequency_before, frequency_after;
  // PerTet, held bodies: the compliance under each local load (hierarchy/calibration_loads.hpp)
  // over the finest level's; fitted only when `local_fitted` (the global targets held with it).
  std::vector<double> local_before, local_after;
  bool local_fitted = false;
  int iterations = 0;
};

/// The ratio arrays of LevelCalibration by quantity and moment, for what stores them (log.h5's
/// calibration_<quantity>_ratio_<when> attributes, the calibration cache's <quantity>_<when>).
struct CalibrationRatios {
  const char* quantity;  // sag, peak, frequency
  const char* when;      // before, after
  std::vector<double> LevelCalibration::*member;
};
inline constexpr CalibrationRatios kCalibrationRatios[] = {
    {"sag", "before", &LevelCalibration::sag_before},
    {"sag", "after", &LevelCalibration::sag_after},
    {"peak", "before", &LevelCalibration::peak_before},
    {"peak", "after", &LevelCalibration::peak_after},
    {"frequency", "before", &LevelCalibration::frequency_before},
    {"frequency", "after", &LevelCalibration::frequency_after},
    {"local", "before", &LevelCalibration::local_before},
    {"local", "after", &LevelCalibration::local_after}};

/// One entry per level, the last (finest) one uncalibrated. `fixed`: per level, one flag per
/// point (as HierarchySetup::fixed). Every level must be held at three points or more, or none
/// at all (a free body: frequencies only); anything else is an InputError.
/// `kind` PerTet also gives each tet of a coarser level seven factors on the level's tensor,
/// fitted with it to the finest level's largest displacements, its sags at the finest points and
/// its local loads too (docs/hierarchy.md "Per-tet tensors").
std::vector<LevelCalibration> calibrate_levels(
    const std::vector<const TetMesh*>& meshes, const MaterialLaw& law,
    const std::vector<std::vector<std::uint8_t>>& fixed,
    CalibrationKind kind = CalibrationKind::Orthotropic);

}  // namespace mrsim
