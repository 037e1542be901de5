#pragma once
// The typed, validated scenario the simulation consumes. It is built only from a JSON document
// that already passed schemas/scenario.schema.json with defaults injected, so every field here
// is set. All quantities are SI; `object.units` only describes the mesh files.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/vec.hpp"
#include "mesh/mesh_reader.hpp"
#include "physics/material_law.hpp"
#include "hierarchy/calibration_kind.hpp"
#include "hierarchy/coupling_kind.hpp"
#include "io/frame_compression.hpp"
#include "time/integrator_kind.hpp"

namespace mrsim {

// The scenario speaks the physics' and the integrators' own enums (one definition each).
using StrainModel = StrainMeasure;   // Cauchy, GreenLagrange
using IntegratorKind = Integrator;   // ModifiedEuler, StoermerVerlet, SemiImplicit

struct LevelSpec {
  std::filesystem::path mesh;  // absolute, resolved against the scenario file's folder
};

struct MaterialSpec {
  StrainModel model = StrainModel::GreenLagrange;
  double lambda = 0, mu = 0;                // Lamé coefficients, Pa (always filled)
  double youngs_modulus = 0, poisson = 0;   // derived or given (always filled, both logged)
  double density = 0;                       // kg/m^3
  double phi = 0, psi = 0;                  // damping on the strain rate, Pa.s
};

struct FixedRegion {
  enum class Kind { Box, HalfSpace, Ids } kind = Kind::Box;
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();      // Box, metres
  Vec3 point = Vec3::Zero(), normal = Vec3::Zero(); // HalfSpace: fixes (X - point).normal >= 0
  std::vector<int> ids;                              // Ids: 0-based vertex ids of the level
  int level = -1;                                    // -1: every level
};

/// A total force spread over the boundary faces inside a box (scenario `loads`).
struct SurfaceLoadSpec {
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();  // box, metres
  Vec3 force = Vec3::Zero();                    // N, at factor 1
  std::vector<std::pair<double, double>> profile{{0.0, 1.0}};  // (time s, factor), increasing
};

/// A tool pose of a keyframe trajectory.
struct KeyframeSpec {
  double t = 0;                              // s
  Vec3 position = Vec3::Zero();              // m
  std::array<double, 4> orientation{1, 0, 0, 0};  // w, x, y, z (tool -> world), as written
};

/// One rigid tool (scenario `tool` / `tools`; built into contact/tool.hpp by the simulation).
struct ToolSpec {
  std::string name;
  std::string shape;                 // "sphere", "capsule", "flat_cylinder"
  double radius = 0, length = 0;     // m (length: capsule segment / punch height)
  std::vector<KeyframeSpec> keyframes;  // when csv is empty
  std::filesystem::path csv;         // absolute; a recorded trajectory
  bool smooth = false;               // interpolation
  double stiffness = 0;              // Pa/m; 0 = "auto" (per skin vertex, contact/skin_contact.hpp)
  double damping = 0;                // Pa.s/m
};

struct BudgetSpec {
  bool realtime = false;
  double fraction = 0.95;  // of frame_dt
};

struct InitialSpec {
  Vec3 velocity = Vec3::Zero();          // m/s, uniform
  Vec3 angular_velocity = Vec3::Zero();  // rad/s, about the centre of mass
};

struct TimeSpec {
  IntegratorKind integrator = IntegratorKind::ModifiedEuler;
  double frame_dt = 0.04;  // s, display frame
  int substeps = 0;        // simulation steps per frame; 0 = computed from the meshes
  double courant = 1.0;    // fraction of the stable-step estimate used (stable_step.hpp)
  bool adapt_substeps = true;  // more substeps when the estimate in force needs them
  double duration = 1.0;   // s
  double divergence_energy_factor = 1.0;  // see simulation/divergence.hpp
};

struct SpaceAdaptivitySpec {
  bool enabled = true;
  double refine_above = 0.05, coarsen_below = 0.0125;  // on c = h |Δu| (dimensionless)
  int max_level = -1;                 // -1: the last level
  std::int64_t max_active_points = 0;  // 0: no cap
  int min_dwell_frames = 5;
  int calm_frames = 1;         // successive calm frame ends before a merge (1: the thesis)
  bool contact_refine = true;  // refine ahead of the tools (look-ahead), not only on c
  bool predict = false;        // c also on u + ½ T² (g + f_ext/m), T = frame_dt (no lag)
  int split_checks = 1;        // splits decided this many times a frame (merges at its end)
  Coupling coupling = Coupling::Energy;
};

struct TimeAdaptivitySpec {
  bool enabled = false;
  double velocity_change = 0.01;  // β of method.md §5.2 (dimensionless)
};

struct OutputSpec {
  std::filesystem::path dir;  // output folder
  int every = 1;              // write a VTK frame every N display frames
  bool vtk = true;            // write frames.pvd and frames/
  int checkpoint_every = 0;   // write checkpoint.h5 every N display frames; 0: only when interrupted
  FrameCompression compression = FrameCompression::Lz4;  // of the frames' binary data
};

struct Scenario {
  std::string name;
  std::filesystem::path source;  // the YAML file it came from
  std::vector<LevelSpec> levels;
  LengthUnit units = LengthUnit::Metre;
  // object.calibration (hierarchy/level_calibration.hpp); the schema's default
  CalibrationKind calibration = CalibrationKind::PerTet;
  std::filesystem::path skin;  // absolute; empty: the finest level's boundary
  LengthUnit skin_units = LengthUnit::Metre;  // of the skin file (default: object.units)
  MaterialSpec material;
  std::vector<FixedRegion> fixed;
  std::vector<SurfaceLoadSpec> loads;
  std::vector<ToolSpec> tools;  // `tool` or `tools`
  Vec3 gravity = Vec3::Zero();
  InitialSpec initial;
  TimeSpec time;
  SpaceAdaptivitySpec space;
  TimeAdaptivitySpec time_levels;
  BudgetSpec budget;
  OutputSpec output;
  nlohmann::json resolved;  // the validated document, every default explicit, material.derived
};

/// Reads a YAML scenario, applies `--set key.path=value` overrides, validates against
/// schemas/scenario.schema.json, injects defaults and builds the typed scenario.
/// Throws InputError (exit 2) naming the file, the key path and the YAML line/column.
Scenario load_scenario(const std::filesystem::path& file,
                       const std::vector<std::string>& overrides = {});

/// load_scenario for YAML text already in memory (e.g. a resolved scenario read back from a
/// run's output). `source` names the text in messages and anchors relative mesh paths.
Scenario load_scenario_text(std::string_view yaml, const std::filesystem::path& source,
                            const std::vector<std::string>& overrides = {});

/// The resolved scenario as YAML text (what `mrsim check` prints and `scenario.yaml` holds).
std::string resolved_yaml(const Scenario& scenario);

/// Path of the schema file used for validation.
std::filesystem::path schema_path();

}  // namespace mrsim
