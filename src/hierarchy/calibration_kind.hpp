#pragma once
namespace mrsim {

// What object.calibration gives the coarser levels (docs/hierarchy.md "Calibrated levels").
enum class CalibrationKind {
  None,         // the material as given on every level (the thesis)
  Orthotropic,  // one orthotropic tensor per level, fitted to the finest level's sag and modes
  PerTet,       // that tensor times one factor per tet, fitted to its sag, peak and modes
};

}  // namespace mrsim
