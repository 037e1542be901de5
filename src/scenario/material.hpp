#pragma once
// The two usual parametrisations of isotropic linear elasticity: Lamé (lambda, mu) and
// engineering (Young's modulus E, Poisson's ratio nu). Users give either; both are logged.
#include <nlohmann/json.hpp>

namespace mrsim::scenario {

struct LameParameters {
  double lambda = 0, mu = 0;  // Pa
};

struct EngineeringParameters {
  double youngs_modulus = 0;  // Pa
  double poisson_ratio = 0;   // dimensionless
};

/// E = mu (3 lambda + 2 mu) / (lambda + mu), nu = lambda / (2 (lambda + mu)); needs mu > 0.
EngineeringParameters engineering_from_lame(const LameParameters& lame);

/// lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)); needs 0 <= nu < 0.5.
LameParameters lame_from_engineering(const EngineeringParameters& engineering);

/// Writes `material.derived` = {lambda, mu, youngs_modulus, poisson_ratio} computed from the
/// pair the (schema-valid) `material` mapping gives, replacing any earlier `derived`.
void add_derived_elastic_constants(nlohmann::json& material);

}  // namespace mrsim::scenario
